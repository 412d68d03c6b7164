#include "photon_tracer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>

#include "../lights/cpu_lights.hpp"
#include "glpreview/render/ggx.hpp"
#include "glpreview/render/sphere_fresnel.hpp"
#include "glpreview/render/worker_threads.hpp"

namespace metalfit::glpreview {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kRayEpsilon = 1e-7;  // m: a reflected photon leaves its wall beyond this
constexpr double kKernelRadius = 4;   // σ: the Gaussian is cut there (it keeps 1 − e⁻⁸ of its weight)
constexpr int kMaxGridEdge = 1024;    // nodes per edge of a receiver's grid
constexpr int kChunk = 4096;          // photons per unit of work (each its own random stream)

double safe(double d) { return std::abs(d) < 1e-12 ? (d < 0 ? -1e-12 : 1e-12) : d; }

// Where the ray from o (inside the room) along unit d leaves it: its parameter and the face.
double room_exit(const Room& room, Vec3 o, Vec3 d, Receiver& face) {
    double t_best = kInf;
    int axis = 0;
    for (int i = 0; i < 3; ++i) {
        const double inv = 1.0 / safe(d[i]);
        const double t = ((inv > 0 ? room.max[i] : room.min[i]) - o[i]) * inv;
        if (t < t_best) {
            t_best = t;
            axis = i;
        }
    }
    const bool positive = d[axis] > 0;
    face = axis == 1   ? (positive ? Receiver::ceiling : Receiver::floor)
           : axis == 0 ? (positive ? Receiver::wall_x_max : Receiver::wall_x_min)
                       : (positive ? Receiver::wall_z_max : Receiver::wall_z_min);
    return t_best;
}

// A photon's spectral (or RGB) throughput.
struct Throughput {
    std::vector<double> spectrum;
    RGB rgb{1, 1, 1};
};

struct Deposit {
    int face;
    ReceiverMap::Photon photon;
};

struct ChunkResult {
    std::vector<Deposit> deposits;
    std::vector<PhotonPath> paths;
    std::vector<PathBounce> bounces;
    PhotonBudget budget;
};

void build_grid(ReceiverMap& map, double sigma);

// The receivers' grids, one face per thread.
void build_grids(std::array<ReceiverMap, kReceivers>& receivers, double sigma, int threads) {
    std::vector<std::size_t> faces;
    for (std::size_t f = 0; f < kReceivers; ++f)
        if (!receivers[f].photons.empty()) faces.push_back(f);
    if (faces.empty()) return;
    std::atomic<std::size_t> next{0};
    run_on_threads(std::min(threads > 0 ? threads : 64, static_cast<int>(faces.size())), [&] {
        for (std::size_t k = next++; k < faces.size(); k = next++) build_grid(receivers[faces[k]], sigma);
    });
}

// Bins the photons (cloud in cell) on a grid around them and convolves it with the normalised Gaussian.
void build_grid(ReceiverMap& map, double sigma) {
    if (map.photons.empty()) return;
    double u_lo = kInf, u_hi = -kInf, v_lo = kInf, v_hi = -kInf;
    for (const auto& p : map.photons) {
        u_lo = std::min(u_lo, p.u), u_hi = std::max(u_hi, p.u);
        v_lo = std::min(v_lo, p.v), v_hi = std::max(v_hi, p.v);
    }
    const double margin = (kKernelRadius + 1) * sigma;
    u_lo -= margin, v_lo -= margin, u_hi += margin, v_hi += margin;
    map.step = std::max({sigma / 6, (u_hi - u_lo) / (kMaxGridEdge - 1), (v_hi - v_lo) / (kMaxGridEdge - 1)});
    map.u0 = u_lo, map.v0 = v_lo;
    map.nu = static_cast<int>(std::ceil((u_hi - u_lo) / map.step)) + 1;
    map.nv = static_cast<int>(std::ceil((v_hi - v_lo) / map.step)) + 1;
    const std::size_t nu = static_cast<std::size_t>(map.nu), nv = static_cast<std::size_t>(map.nv);
    std::vector<double> bins(nu * nv * 3, 0.0);
    for (const auto& p : map.photons) {
        const double x = (p.u - map.u0) / map.step, y = (p.v - map.v0) / map.step;
        const auto i = static_cast<std::size_t>(x), j = static_cast<std::size_t>(y);
        const double fx = x - static_cast<double>(i), fy = y - static_cast<double>(j);
        const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        const std::size_t cell[4] = {j * nu + i, j * nu + i + 1, (j + 1) * nu + i, (j + 1) * nu + i + 1};
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) bins[cell[k] * 3 + static_cast<std::size_t>(c)] += w[k] * p.power[c];
    }
    // The Gaussian's taps, normalised on the grid (Σ g = 1 per axis), so that Σ E step² = the photons' power.
    const int radius = static_cast<int>(std::ceil(kKernelRadius * sigma / map.step));
    std::vector<double> taps(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0;
    for (int k = -radius; k <= radius; ++k) {
        const double x = k * map.step / sigma;
        sum += taps[static_cast<std::size_t>(k + radius)] = std::exp(-0.5 * x * x);
    }
    for (double& t : taps) t /= sum;
    std::vector<double> along_u(bins.size(), 0.0);
    for (std::size_t j = 0; j < nv; ++j)
        for (std::size_t i = 0; i < nu; ++i)
            for (int k = -radius; k <= radius; ++k) {
                const long ii = static_cast<long>(i) + k;
                if (ii < 0 || ii >= map.nu) continue;
                const double t = taps[static_cast<std::size_t>(k + radius)];
                for (std::size_t c = 0; c < 3; ++c)
                    along_u[(j * nu + i) * 3 + c] += t * bins[(j * nu + static_cast<std::size_t>(ii)) * 3 + c];
            }
    map.grid.assign(bins.size(), 0.0f);
    const double area = map.step * map.step;
    for (std::size_t j = 0; j < nv; ++j)
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t c = 0; c < 3; ++c) {
                double e = 0;
                for (int k = -radius; k <= radius; ++k) {
                    const long jj = static_cast<long>(j) + k;
                    if (jj < 0 || jj >= map.nv) continue;
                    e += taps[static_cast<std::size_t>(k + radius)] *
                         along_u[(static_cast<std::size_t>(jj) * nu + i) * 3 + c];
                }
                map.grid[(j * nu + i) * 3 + c] = static_cast<float>(e / area);
            }
}

}  // namespace

const char* receiver_name(Receiver receiver) {
    switch (receiver) {
        case Receiver::floor: return "floor";
        case Receiver::ceiling: return "ceiling";
        case Receiver::wall_x_min: return "wall_x_min";
        case Receiver::wall_x_max: return "wall_x_max";
        case Receiver::wall_z_min: return "wall_z_min";
        case Receiver::wall_z_max: return "wall_z_max";
    }
    return "";
}

int receiver_at(const Room& room, Vec3 p, Vec3 n) {
    const double tolerance =
        1e-6 * std::max({room.max.x - room.min.x, room.max.y - room.min.y, room.max.z - room.min.z, 1.0});
    if (n.y > 0.5 && std::abs(p.y - room.min.y) < tolerance) return static_cast<int>(Receiver::floor);
    if (n.y < -0.5 && std::abs(p.y - room.max.y) < tolerance) return static_cast<int>(Receiver::ceiling);
    if (n.x > 0.5 && std::abs(p.x - room.min.x) < tolerance) return static_cast<int>(Receiver::wall_x_min);
    if (n.x < -0.5 && std::abs(p.x - room.max.x) < tolerance) return static_cast<int>(Receiver::wall_x_max);
    if (n.z > 0.5 && std::abs(p.z - room.min.z) < tolerance) return static_cast<int>(Receiver::wall_z_min);
    if (n.z < -0.5 && std::abs(p.z - room.max.z) < tolerance) return static_cast<int>(Receiver::wall_z_max);
    return -1;
}

std::array<double, 2> receiver_coordinates(Receiver receiver, Vec3 p) {
    switch (receiver) {
        case Receiver::floor:
        case Receiver::ceiling: return {p.x, p.z};
        case Receiver::wall_x_min:
        case Receiver::wall_x_max: return {p.z, p.y};
        case Receiver::wall_z_min:
        case Receiver::wall_z_max: return {p.x, p.y};
    }
    return {0, 0};
}

CausticMap::CausticMap(std::array<ReceiverMap, kReceivers> receivers, PhotonBudget budget, double sigma)
    : receivers_(std::move(receivers)), budget_(budget), sigma_(sigma) {}

RGB CausticMap::irradiance(Receiver receiver, double u, double v) const {
    const ReceiverMap& m = receivers_[static_cast<std::size_t>(receiver)];
    if (m.grid.empty()) return {0, 0, 0};
    const double x = (u - m.u0) / m.step, y = (v - m.v0) / m.step;
    if (!(x >= 0 && y >= 0 && x < m.nu - 1 && y < m.nv - 1)) return {0, 0, 0};
    const auto i = static_cast<std::size_t>(x), j = static_cast<std::size_t>(y);
    const double fx = x - static_cast<double>(i), fy = y - static_cast<double>(j);
    const auto nu = static_cast<std::size_t>(m.nu);
    RGB e{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
        const auto at = [&](std::size_t a, std::size_t b) {
            return static_cast<double>(m.grid[(b * nu + a) * 3 + static_cast<std::size_t>(c)]);
        };
        e[c] = (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
               fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
    }
    return e;
}

RGB CausticMap::irradiance_at(const Room& room, Vec3 p, Vec3 n) const {
    const int face = receiver_at(room, p, n);
    if (face < 0) return {0, 0, 0};
    const auto [u, v] = receiver_coordinates(static_cast<Receiver>(face), p);
    return irradiance(static_cast<Receiver>(face), u, v);
}

RGB CausticMap::exact_irradiance(Receiver receiver, double u, double v) const {
    const ReceiverMap& m = receivers_[static_cast<std::size_t>(receiver)];
    const double cut = kKernelRadius * sigma_, norm = 1.0 / (2 * kPi * sigma_ * sigma_);
    RGB e{0, 0, 0};
    for (const auto& p : m.photons) {
        const double du = p.u - u, dv = p.v - v;
        if (std::abs(du) > cut || std::abs(dv) > cut) continue;
        const double r2 = du * du + dv * dv;
        if (r2 > cut * cut) continue;
        e = e + norm * std::exp(-0.5 * r2 / (sigma_ * sigma_)) * p.power;
    }
    return e;
}

CausticMap trace_caustics(const Scene& scene, const Rings& rings, const Lights& lights, const PhotonFresnel& fresnel,
                          const PhotonOptions& options) {
    const bool spectral = !fresnel.spectral.empty();
    if (spectral ? (fresnel.spectral.size() != rings.rings.size() || !fresnel.uplift)
                 : fresnel.rgb.size() != rings.rings.size())
        throw std::invalid_argument("trace_caustics: one Fresnel per ring");
    if (!(options.photons > 0 && options.sigma > 0)) throw std::invalid_argument("trace_caustics: photons, sigma");
    const Room& room = scene.environment.room;
    const Vec3 room_size = room.max - room.min;
    const double room_diagonal = length(room_size);

    // The units of work: (light, ring, chunk), each with its own random stream.
    struct Job {
        std::size_t light, ring;
        int first, count;
    };
    std::vector<Job> jobs;
    for (std::size_t l = 0; l < lights.lights.size(); ++l) {
        if (lights.lights[l].type == LightType::sphere) continue;  // not traced (docs/preview.md)
        for (std::size_t r = 0; r < rings.rings.size(); ++r)
            for (int first = 0; first < options.photons; first += kChunk)
                jobs.push_back({l, r, first, std::min(kChunk, options.photons - first)});
    }
    std::vector<ChunkResult> results(jobs.size());

    const auto trace_job = [&](const Job& job, ChunkResult& out) {
        const Light& light = lights.lights[job.light];
        const BoundingSphere bounds = rings.rings[job.ring].bounds();
        std::mt19937_64 random(options.seed ^ (0x9E3779B97F4A7C15ull * (job.light * 64 + job.ring + 1)) ^
                               (static_cast<std::uint64_t>(job.first) << 20));
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        // The photons' common geometry: a directional beam's disk, a local light's cone.
        const double n = options.photons;
        Vec3 axis;
        double cos_max = -1, weight = 0;  // weight: W per photon and per unit of the light's power
        if (light.type == LightType::directional) {
            axis = light.direction;
            weight = kPi * bounds.radius * bounds.radius / n;
        } else {
            const Vec3 to = bounds.centre - light.position;
            const double dist = length(to);
            axis = dist > 0 ? (1.0 / dist) * to : Vec3{0, -1, 0};
            cos_max = dist > bounds.radius ? std::sqrt(1 - bounds.radius * bounds.radius / (dist * dist)) : -1;
            weight = 2 * kPi * (1 - cos_max) / n;
        }
        const ggx::Frame frame(axis);
        Throughput throughput;
        if (spectral) throughput.spectrum.resize(fresnel.uplift->size());
        for (int k = 0; k < job.count; ++k) {
            const double u1 = uniform(random), u2 = uniform(random);
            ++out.budget.traced;
            Vec3 o, d;
            double w = weight;
            if (light.type == LightType::directional) {
                const double r = bounds.radius * std::sqrt(u1), phi = 2 * kPi * u2;
                const Vec3 q = bounds.centre + frame.to_world({r * std::cos(phi), r * std::sin(phi), 0});
                d = axis;
                o = q - (bounds.radius + room_diagonal) * d;  // outside the room: walls do not stop sunlight
            } else {
                const double cos_t = 1 - u1 * (1 - cos_max), sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
                const double phi = 2 * kPi * u2;
                d = normalize(frame.to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t}));
                o = light.position;
                if (light.type == LightType::spot) w *= spot_weight(light, dot(d, light.direction));
            }
            if (!(w > 0)) continue;
            std::optional<RingHit> hit = intersect_rings(rings.rings, o, d, 0, kInf);
            // Another ring first: its own photons carry that light.
            if (!hit || hit->ring != job.ring) continue;
            if (occluded_by_spheres_and_boxes(scene, o, d, hit->t)) continue;
            const RGB power = w * light.power();
            ++out.budget.hits;
            out.budget.intercepted = out.budget.intercepted + power;
            if (spectral)
                std::fill(throughput.spectrum.begin(), throughput.spectrum.end(), 1.0);
            else
                throughput.rgb = {1, 1, 1};
            const std::size_t path_start = out.bounces.size();
            for (int bounce = 0;; ++bounce) {
                const double mu = std::clamp(-dot(d, hit->normal), 0.0, 1.0);
                if (options.record_paths) out.bounces.push_back({static_cast<std::uint32_t>(hit->ring), mu});
                if (spectral)
                    fresnel.spectral[hit->ring]->multiply(mu, throughput.spectrum);
                else
                    throughput.rgb = throughput.rgb * (*fresnel.rgb[hit->ring])(mu);
                std::optional<RGB> carried_now;  // the photon's power now, in RGB (once per bounce)
                const auto carried = [&] {
                    if (!carried_now)
                        carried_now = spectral ? w * fresnel.uplift->rgb(throughput.spectrum, light.power())
                                               : throughput.rgb * power;
                    return *carried_now;
                };
                if (bounce == 0) out.budget.reflected = out.budget.reflected + carried();
                if (bounce == 1) ++out.budget.multiple;
                o = hit->point;
                d = normalize(d - 2 * dot(d, hit->normal) * hit->normal);
                Receiver face{};
                const double t_room = room_exit(room, o, d, face);
                hit = intersect_rings(rings.rings, o, d, kRayEpsilon, t_room);
                const double t_next = hit ? hit->t : t_room;
                if (occluded_by_spheres_and_boxes(scene, o, d, t_next) || (hit && bounce + 1 >= kMaxPhotonBounces)) {
                    out.budget.absorbed = out.budget.absorbed + carried();
                    out.bounces.resize(path_start);
                    break;
                }
                if (hit) continue;
                const RGB deposited = carried();
                const auto [u, v] = receiver_coordinates(face, o + t_room * d);
                out.deposits.push_back({static_cast<int>(face), {u, v, deposited}});
                if (options.record_paths)
                    out.paths.push_back({power, static_cast<int>(face), u, v, static_cast<std::uint32_t>(path_start),
                                         static_cast<std::uint32_t>(out.bounces.size() - path_start)});
                out.budget.deposited = out.budget.deposited + deposited;
                if (bounce > 0) out.budget.deposited_multiple = out.budget.deposited_multiple + deposited;
                break;
            }
        }
    };
    std::atomic<std::size_t> next{0};
    run_on_threads(options.threads, [&] {
        for (std::size_t j = next++; j < jobs.size(); j = next++) trace_job(jobs[j], results[j]);
    });

    std::array<ReceiverMap, kReceivers> receivers;
    PhotonBudget budget;
    std::vector<PhotonPath> paths;
    std::vector<PathBounce> path_bounces;
    for (const ChunkResult& r : results) {  // in job order: the same map whatever the threads
        for (PhotonPath path : r.paths) {
            path.first += static_cast<std::uint32_t>(path_bounces.size());
            paths.push_back(path);
        }
        path_bounces.insert(path_bounces.end(), r.bounces.begin(), r.bounces.end());
        for (const Deposit& deposit : r.deposits) {
            ReceiverMap& m = receivers[static_cast<std::size_t>(deposit.face)];
            m.photons.push_back(deposit.photon);
            m.power = m.power + deposit.photon.power;
        }
        budget.intercepted = budget.intercepted + r.budget.intercepted;
        budget.reflected = budget.reflected + r.budget.reflected;
        budget.deposited = budget.deposited + r.budget.deposited;
        budget.absorbed = budget.absorbed + r.budget.absorbed;
        budget.deposited_multiple = budget.deposited_multiple + r.budget.deposited_multiple;
        budget.traced += r.budget.traced;
        budget.hits += r.budget.hits;
        budget.multiple += r.budget.multiple;
    }
    build_grids(receivers, options.sigma, options.threads);
    CausticMap map(std::move(receivers), budget, options.sigma);
    map.paths = std::move(paths);
    map.path_bounces = std::move(path_bounces);
    return map;
}

CausticMap reweight(const CausticMap& traced, const PhotonFresnel& fresnel, int threads) {
    const bool spectral = !fresnel.spectral.empty();
    std::vector<ReceiverMap::Photon> weighed(traced.paths.size());
    std::atomic<std::size_t> next{0};
    constexpr std::size_t kBlock = 4096;
    run_on_threads(threads, [&] {
        std::vector<double> spectrum(spectral ? fresnel.uplift->size() : 0);
        for (std::size_t start = (next += kBlock) - kBlock; start < weighed.size(); start = (next += kBlock) - kBlock)
            for (std::size_t i = start; i < std::min(start + kBlock, weighed.size()); ++i) {
                const PhotonPath& path = traced.paths[i];
                RGB power = path.power;
                if (spectral) {
                    std::fill(spectrum.begin(), spectrum.end(), 1.0);
                    for (std::uint32_t k = 0; k < path.count; ++k) {
                        const PathBounce& b = traced.path_bounces[path.first + k];
                        fresnel.spectral[b.ring]->multiply(b.mu, spectrum);
                    }
                    power = fresnel.uplift->rgb(spectrum, path.power);
                } else {
                    for (std::uint32_t k = 0; k < path.count; ++k) {
                        const PathBounce& b = traced.path_bounces[path.first + k];
                        power = power * (*fresnel.rgb[b.ring])(b.mu);
                    }
                }
                weighed[i] = {path.u, path.v, power};
            }
    });
    std::array<ReceiverMap, kReceivers> receivers;
    PhotonBudget budget = traced.budget();
    budget.deposited = budget.deposited_multiple = {0, 0, 0};
    for (std::size_t i = 0; i < weighed.size(); ++i) {
        ReceiverMap& m = receivers[static_cast<std::size_t>(traced.paths[i].face)];
        m.photons.push_back(weighed[i]);
        m.power = m.power + weighed[i].power;
        budget.deposited = budget.deposited + weighed[i].power;
        if (traced.paths[i].count > 1) budget.deposited_multiple = budget.deposited_multiple + weighed[i].power;
    }
    build_grids(receivers, traced.sigma(), threads);
    return CausticMap(std::move(receivers), budget, traced.sigma());
}

CausticMap with_sigma(const CausticMap& traced, double sigma, int threads) {
    std::array<ReceiverMap, kReceivers> receivers;
    for (int r = 0; r < kReceivers; ++r) {
        receivers[static_cast<std::size_t>(r)].photons = traced.receiver(static_cast<Receiver>(r)).photons;
        receivers[static_cast<std::size_t>(r)].power = traced.receiver(static_cast<Receiver>(r)).power;
    }
    build_grids(receivers, sigma, threads);
    return CausticMap(std::move(receivers), traced.budget(), sigma);
}

IrradiancePeak measure_irradiance(const std::vector<float>& texels, int width, int height, double u0, double v0,
                                  double step, const RGB& weights) {
    if (texels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
        throw std::invalid_argument("measure_irradiance: texels are not width × height RGB");
    IrradiancePeak peak;
    double best = -kInf;
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            const std::size_t at =
                (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)) *
                3;
            const RGB e{texels[at], texels[at + 1], texels[at + 2]};
            peak.power = peak.power + step * step * e;
            const double y = weights.r * e.r + weights.g * e.g + weights.b * e.b;
            if (y > best) {
                best = y;
                peak.irradiance = e;
                peak.u = u0 + column * step;
                peak.v = v0 + row * step;
            }
        }
    return peak;
}

IrradiancePeak measure_receiver(const CausticMap& map, Receiver receiver, const RGB& weights) {
    const ReceiverMap& m = map.receiver(receiver);
    if (m.grid.empty()) return {};
    return measure_irradiance(m.grid, m.nu, m.nv, m.u0, m.v0, m.step, weights);
}

}  // namespace metalfit::glpreview
