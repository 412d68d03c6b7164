// The caustics' CPU reference (issue 35 item 4; docs/preview.md, "Caustics: the reference and the per-model table"):
// a photon tracer. Photons leave each light aimed at each ring's bounding sphere with their share of the light's
// power (directional: irradiance × the beam's cross-section πR_b² / N; point and spot: intensity × the solid angle
// of the cone subtending the sphere / N, a spot's cone weight as cpu_lights' spot_weight; sphere lights are not
// traced), reach the ring unless a sphere or room box (or another ring first) stops them, reflect off the walls —
// several times if they meet a wall again, up to kMaxPhotonBounces — with the exact spectral Fresnel F(λ, μ) of the
// ring's material (or, for the per-model table, a Fresnel in RGB), and are deposited where they meet the room's
// floor, walls or ceiling; a photon that meets a sphere or a room box after the ring is absorbed (no caustic on
// them). A photon carries its spectral throughput; at its deposit the light's RGB is lifted to a spectrum and the
// product integrated to the scene's RGB as the spectral reference does (render/rgb_uplift.hpp). The irradiance is
// the density estimate with a normalised Gaussian of σ = caustics.filter_width in the receiver's plane, in W/m².
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "../lights/light.hpp"
#include "../rings/ring.hpp"
#include "glpreview/render/rgb_uplift.hpp"
#include "glpreview/render/spectral_fresnel.hpp"
#include "glpreview/scene/scene.hpp"

namespace metalfit::glpreview {

struct SphereFresnel;

inline constexpr int kMaxPhotonBounces = 16;

// The room's six faces, the receivers of the caustics; a face's plane coordinates (u, v): floor and ceiling (x, z),
// the x walls (z, y), the z walls (x, y).
enum class Receiver { floor, ceiling, wall_x_min, wall_x_max, wall_z_min, wall_z_max };
inline constexpr int kReceivers = 6;
const char* receiver_name(Receiver receiver);  // "floor", "ceiling", "wall_x_min", …
// The receiver whose plane p lies on (within 1e-6 of the room's size) with inward normal n; −1 when none (a box's
// face, a point off the room's walls).
int receiver_at(const Room& room, Vec3 p, Vec3 n);
// A point's (u, v) on a receiver's plane.
std::array<double, 2> receiver_coordinates(Receiver receiver, Vec3 p);

// The Fresnel the rings reflect photons with: per ring, the exact spectral one (with `uplift`), or else an RGB one.
struct PhotonFresnel {
    std::vector<const SpectralFresnel*> spectral;
    const RgbUplift* uplift = nullptr;
    std::vector<const SphereFresnel*> rgb;  // used when `spectral` is empty
};

struct PhotonOptions {
    int photons = 1 << 20;  // per light and ring
    double sigma = 0.03;    // m, the Gaussian's σ
    int threads = 0;        // 0: all cores
    std::uint64_t seed = 35;
    bool record_paths = false;  // keep each deposited photon's reflections (CausticMap::paths, reweight)
};

// A deposited photon's path, to weigh it again with another Fresnel (the photons' geometry does not depend on it):
// the light's power it left with, where it landed, and its reflections (ring, μ) in CausticMap::path_bounces.
struct PhotonPath {
    RGB power;
    int face = 0;
    double u = 0, v = 0;
    std::uint32_t first = 0, count = 0;
};
struct PathBounce {
    std::uint32_t ring = 0;
    double mu = 0;
};

// What the photons carried, summed over every light and ring (W, RGB).
struct PhotonBudget {
    RGB intercepted{0, 0, 0};         // reached a ring's wall
    RGB reflected{0, 0, 0};           // left the first wall (× F)
    RGB deposited{0, 0, 0};           // on the room's faces
    RGB absorbed{0, 0, 0};            // stopped by a sphere or room box after a reflection, or after kMaxPhotonBounces
    RGB deposited_multiple{0, 0, 0};  // the part of `deposited` that photons reflected more than once carried
    std::int64_t traced = 0, hits = 0, multiple = 0;  // photons traced, reaching a ring, reflected more than once
};

// One receiver's photons and its irradiance on a grid: the photons binned (cloud in cell) on a grid of step ≤ σ/6,
// then convolved with the normalised Gaussian (separable, ±4σ); irradiance() reads it bilinearly.
struct ReceiverMap {
    struct Photon {
        double u = 0, v = 0;
        RGB power;
    };
    std::vector<Photon> photons;
    RGB power{0, 0, 0};  // Σ of the photons' power (W)
    double u0 = 0, v0 = 0, step = 1;
    int nu = 0, nv = 0;
    std::vector<float> grid;  // nu × nv × 3, W/m²
};

class CausticMap {
public:
    CausticMap() = default;
    CausticMap(std::array<ReceiverMap, kReceivers> receivers, PhotonBudget budget, double sigma);

    // The caustic irradiance E (W/m²) at (u, v) of a receiver, from the grid; and at a point of the room with inward
    // normal n (zero off the room's faces).
    RGB irradiance(Receiver receiver, double u, double v) const;
    RGB irradiance_at(const Room& room, Vec3 p, Vec3 n) const;
    // The density estimate itself at (u, v), summed over every photon (for tests: the grid's accuracy).
    RGB exact_irradiance(Receiver receiver, double u, double v) const;
    const ReceiverMap& receiver(Receiver r) const { return receivers_[static_cast<std::size_t>(r)]; }
    const PhotonBudget& budget() const { return budget_; }
    double sigma() const { return sigma_; }
    bool empty() const { return budget_.hits == 0; }
    // With PhotonOptions::record_paths: every deposited photon's path, in deposit order.
    std::vector<PhotonPath> paths;
    std::vector<PathBounce> path_bounces;

private:
    std::array<ReceiverMap, kReceivers> receivers_;
    PhotonBudget budget_;
    double sigma_ = 0.03;
};

// Traces `options.photons` photons per light and ring of `scene` (its room, spheres and boxes) and density-estimates
// them. `fresnel` holds one entry per ring. Deterministic for a seed, whatever the number of threads.
CausticMap trace_caustics(const Scene& scene, const Rings& rings, const Lights& lights, const PhotonFresnel& fresnel,
                          const PhotonOptions& options);

// The same photons weighed with another Fresnel (one per ring): the receivers' photons, powers and grids, and the
// budget's deposited power (the rest of the budget is the traced map's). `traced` must have recorded its paths.
CausticMap reweight(const CausticMap& traced, const PhotonFresnel& fresnel, int threads = 0);

// The same photons density-estimated with another σ.
CausticMap with_sigma(const CausticMap& traced, double sigma, int threads = 0);

// The brightest point of an irradiance image (luminance weights `weights`) sampled on a grid of texels: what the
// peak of a caustic is measured by, on the reference's grid or on a GPU light map alike.
struct IrradiancePeak {
    double u = 0, v = 0;  // the brightest sample's plane coordinates
    RGB irradiance{0, 0, 0};
    RGB power{0, 0, 0};  // Σ E × texel area: the image's total power (W)
};
// `texels`: width × height RGB, row-major; sample (column, row) lies at (u0 + column·step, v0 + row·step) (a light
// map's texel centres: u0 = the face's edge + step/2) and stands for a step² area.
IrradiancePeak measure_irradiance(const std::vector<float>& texels, int width, int height, double u0, double v0,
                                  double step, const RGB& weights);
// The same on a receiver of a caustic map (its grid).
IrradiancePeak measure_receiver(const CausticMap& map, Receiver receiver, const RGB& weights);

}  // namespace metalfit::glpreview
