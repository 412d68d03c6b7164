// LayerStack: what lies over a metal — an optional thin film (coherent) and an optional smooth clear coat
// (incoherent) — as measured or given indices with their provenance. A Material with layers is the stack "coat over
// film over metal"; the reference curve (reference/reference_curve.hpp) integrates its reflectance
// (optics/stack_reflectance.hpp). docs/colour.md, "Layered metals".
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "libfit/io/material.hpp"

namespace metalfit {

// Films thicker than this are outside the coherent model: over 2 µm, the interference fringes of daylight are finer
// than the film's thickness varies and than the colour matching functions resolve (use a coat for a thick layer).
inline constexpr double kMaxFilmThicknessNm = 2000.0;

// One layer's material: a table or formula (catalog or file, with provenance) or a constant index ("2.2": n = 2.2,
// k = 0, source "constant").
using LayerMaterial = Material;

struct ThinFilm {
    LayerMaterial material;
    double thickness_nm = 0.0;  // 0 ≤ d ≤ kMaxFilmThicknessNm
};

struct ClearCoat {
    LayerMaterial material;              // n_c ≥ 1 (its k, if any, absorbs only when a thickness is given)
    std::optional<double> thickness_nm;  // the path of the absorption; absent: a clear coat
};

// The named finish a stack was loaded as (io/finishes.hpp: data/finishes.json), for the records.
struct FinishName {
    std::string id;    // "anodized-ti-80nm"
    std::string name;  // "anodized titanium, 80 nm"
};

struct LayerStack {
    std::optional<ThinFilm> film;
    std::optional<ClearCoat> coat;
    std::optional<FinishName> finish;  // absent: layers from --film/--coat

    bool empty() const { return !film && !coat; }
};

// "TiO2 (Siefke) film of 80 nm", "coat n = 1.5", "coat PMMA (Szczurowski) 20000 nm thick": for the human output.
std::string describe(const ThinFilm& film);
std::string describe(const ClearCoat& coat);
// "gold under a coat n = 1.5 over a TiO2 (Siefke) film of 80 nm": the whole stack, top down, or the name alone; a
// named finish's name first ("anodized titanium, 80 nm: titanium under a TiO2 (Siefke) film of 80 nm").
std::string describe_stack(const Material& metal);
// The stack's name for a label ("anodized titanium, 80 nm" for a named finish; "titanium + TiO2 60 nm + coat n = 1.5"
// for layers given; the metal's name when bare): short enough for an image's caption.
std::string short_stack_name(const Material& metal);

// The provenance of the layers over `metal` (schemas/common.schema.json, "stack"): the description, and per layer its
// material (id, name, source, file, sha256, reference, data_type) and thickness, and the finish's id and name when
// it is a named finish; null for a bare material. The files are named by record_path against `data_dir`.
nlohmann::ordered_json stack_record(const Material& metal, const std::filesystem::path& data_dir);

// The wavelength at which a layer's index is stated where a format takes one number (OpenPBR coat_ior /
// thin_film_ior, MaterialX dielectric_bsdf ior / thinfilm_ior, glTF iridescenceIor, the export headers and
// records): 550 nm, the middle of the visible range and the peak of the photopic V(λ). docs/export.md, Layered exports.
inline constexpr double kLayerIndexWavelengthNm = 550.0;
// The range over which a layer's dispersion and absorption are summarised (the visible: 380–780 nm, 1 nm steps).
inline constexpr int kLayerVisibleFirstNm = 380;
inline constexpr int kLayerVisibleLastNm = 780;

// One layer material's index as a format that takes constants sees it: n and k at kLayerIndexWavelengthNm (linear
// interpolation, the end values held outside the table, as --extrapolate does), and the extremes of n and k over the
// visible range, which say how far one number misses a dispersive or absorbing layer.
struct LayerIndexSummary {
    double n = 1.0;      // n(550 nm)
    double k = 0.0;      // k(550 nm)
    double n_min = 1.0;  // over 380–780 nm
    double n_max = 1.0;
    double k_max = 0.0;
    // n varies by more than 0.005 over the visible (a constant IOR does not): one number is an approximation.
    bool dispersive() const { return n_max - n_min > 0.005; }
    bool absorbing() const { return k_max > 0.0; }
};
LayerIndexSummary layer_index_summary(const LayerMaterial& material);
// "n(550 nm) = 2.44, k(550 nm) = 0; over 380-780 nm n 2.38-2.91, k ≤ 0.01": one line for the headers.
std::string describe_layer_index(const LayerIndexSummary& summary);

// The one rule for thicknesses: "" when valid, else why not ("thickness -5 nm is negative", "thickness 2500 nm is
// beyond 2 µm: …").
std::string film_thickness_problem(double thickness_nm);
std::string coat_thickness_problem(double thickness_nm);

}  // namespace metalfit
