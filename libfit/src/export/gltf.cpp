// glTF 2.0 export: per material and model a self-contained .gltf asset — one metal material (pbrMetallicRoughness:
// baseColorFactor = the model's F0, metallicFactor 1, roughnessFactor = --roughness) on a UV sphere whose vertices
// and indices are an embedded base64 data: URI buffer — with metalfit's provenance in the material's extras.
// glTF's colours are linear Rec.709 (sRGB primaries, D65), in [0, 1]: another working space is refused
// (require_export_space) and a channel above 1 is clipped, or scaled with --gamut scale (docs/export.md).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include "export/export_formats.hpp"
#include "export/header_provenance.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/version.hpp"
#include "libfit/fit/fit_record.hpp"

namespace metalfit::detail {

namespace {

using Json = nlohmann::ordered_json;

// What a glTF viewer draws for a metal, whatever the extras say: the core metallic BRDF's Fresnel.
constexpr const char* kGltfViewerCurve =
    "Schlick from baseColorFactor to 1 (glTF 2.0's metallic BRDF): what a glTF viewer draws";

static_assert(std::endian::native == std::endian::little,
              "glTF buffers are little-endian; the sphere is written as memory");

// RFC 4648 base64 with padding: what a data: URI's ";base64," carries.
std::string base64(const std::string& bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t v = 0;
        for (std::size_t j = 0; j < 3; ++j) v = (v << 8) | (j < n ? static_cast<unsigned char>(bytes[i + j]) : 0u);
        for (std::size_t j = 0; j < 4; ++j) out += j <= n ? kAlphabet[(v >> (18 - 6 * j)) & 63u] : '=';
    }
    return out;
}

template <typename T>
void append(std::string& bytes, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
}

// The unit sphere (radius 1, +Y up, glTF's convention): a pole at each end and kRings - 1 rings of kSegments
// vertices; the normal of each vertex is its position. Triangles are counter-clockwise seen from outside (glTF's
// front face). Made once: every asset holds the same mesh.
struct Sphere {
    static constexpr int kSegments = 32, kRings = 16;
    std::vector<std::array<float, 3>> vertices;
    std::vector<std::uint16_t> indices;
    std::array<float, 3> min{}, max{};
    std::string buffer;  // positions, then normals, then indices
    std::size_t positions_bytes = 0, indices_bytes = 0;
};

const Sphere& sphere() {
    static const Sphere s = [] {
        Sphere m;
        const auto vertex = [&](double theta, double phi) {
            m.vertices.push_back({static_cast<float>(std::sin(theta) * std::sin(phi)),
                                  static_cast<float>(std::cos(theta)),
                                  static_cast<float>(std::sin(theta) * std::cos(phi))});
        };
        vertex(0.0, 0.0);  // north pole, index 0
        for (int i = 1; i < Sphere::kRings; ++i)
            for (int j = 0; j < Sphere::kSegments; ++j)
                vertex(std::numbers::pi * i / Sphere::kRings, 2.0 * std::numbers::pi * j / Sphere::kSegments);
        vertex(std::numbers::pi, 0.0);               // south pole, the last index
        const auto at = [](int ring, int segment) {  // ring 1 … kRings - 1
            return static_cast<std::uint16_t>(1 + (ring - 1) * Sphere::kSegments + segment % Sphere::kSegments);
        };
        const auto south = static_cast<std::uint16_t>(m.vertices.size() - 1);
        for (int j = 0; j < Sphere::kSegments; ++j) {
            m.indices.insert(m.indices.end(), {0, at(1, j), at(1, j + 1)});
            for (int i = 1; i + 1 < Sphere::kRings; ++i) {
                m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
                m.indices.insert(m.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
            m.indices.insert(m.indices.end(), {at(Sphere::kRings - 1, j), south, at(Sphere::kRings - 1, j + 1)});
        }
        m.min = m.max = m.vertices.front();
        for (const auto& v : m.vertices)
            for (int c = 0; c < 3; ++c) {
                m.min[c] = std::min(m.min[c], v[c]);
                m.max[c] = std::max(m.max[c], v[c]);
            }
        for (const auto& v : m.vertices)
            for (float x : v) append(m.buffer, x);
        m.positions_bytes = m.buffer.size();
        for (const auto& v : m.vertices)
            for (float x : v) append(m.buffer, x);  // the normals: the same unit vectors
        for (std::uint16_t i : m.indices) append(m.buffer, i);
        m.indices_bytes = m.indices.size() * sizeof(std::uint16_t);
        while (m.buffer.size() % 4 != 0) m.buffer += '\0';  // a buffer's length padded to 4 bytes
        return m;
    }();
    return s;
}

Json vec3_json(const std::array<float, 3>& v) { return Json::array({double(v[0]), double(v[1]), double(v[2])}); }

}  // namespace

GltfBaseColor gltf_base_color(const WrittenParameters& written, GamutPolicy gamut) {
    GltfBaseColor out;
    out.f0 = written.model->evaluate(written.params, 1.0);  // the curve at normal incidence (mu = cos 0 = 1)
    out.factor = out.f0;
    const double max = std::max({out.f0.r, out.f0.g, out.f0.b});
    std::string outside;
    for (int c = 0; c < 3; ++c)
        if (out.f0[c] > 1.0 || out.f0[c] < 0.0)
            outside += (outside.empty() ? "" : ", ") + std::string(kChannelNames[c]) + " " + number(out.f0[c]);
    if (outside.empty()) return out;
    if (gamut == GamutPolicy::scale) {
        for (int c = 0; c < 3; ++c) out.factor[c] = std::max(0.0, max > 1.0 ? out.f0[c] / max : out.f0[c]);
        out.adjustment = "F0 outside [0, 1] (" + outside +
                         "): " + (max > 1.0 ? "scaled by 1/" + number(max) : std::string("negative values set to 0")) +
                         " (--gamut scale)";
    } else {
        for (int c = 0; c < 3; ++c) out.factor[c] = std::clamp(out.f0[c], 0.0, 1.0);
        out.adjustment = "F0 outside [0, 1] (" + outside +
                         "): clipped to [0, 1] (glTF's baseColorFactor is in [0, 1]; "
                         "--gamut scale scales instead)";
    }
    return out;
}

std::vector<ExportFile> export_gltf(const std::vector<MaterialExport>& materials, const ExportContext& context) {
    const Sphere& mesh = sphere();
    const std::string uri = "data:application/octet-stream;base64," + base64(mesh.buffer);
    std::vector<ExportFile> files;
    for (const MaterialExport& m : materials)
        for (std::size_t i = 0; i < m.models.size(); ++i) {
            const ModelExport& e = m.models[i];
            const std::string stem = file_stem(context.request.id_prefix, m.fit->material.id, e.written.model->id());
            // A layered material: baseColorFactor is the bare metal's F0, under glTF's clearcoat and iridescence.
            const MaterialExport& bare = base_export(m);
            const std::optional<LayeredParameters> layers =
                m.bare_metal ? layered_parameters(m.fit->material) : std::nullopt;
            const WrittenParameters& w = bare.models[i].written;
            const GltfBaseColor base = gltf_base_color(w, context.request.gamut);
            const Metrics& mt = w.metrics;
            Json params = Json::object();
            const auto parameters = w.model->parameters();
            for (std::size_t i = 0; i < parameters.size(); ++i) {
                const RGB v = w.params.parameter(i);
                params[std::string(parameters[i].name)] = Json::array({v.r, v.g, v.b});
            }
            Json tint = nullptr;
            if (const auto f82 = as_f82_tint(w, *bare.fit->reference)) {
                const RGB t = f82->params.parameter(1);
                tint = Json::array({t.r, t.g, t.b});
            }
            Json provenance = material_identity_json("metalfit.gltf/1", m.fit->material, context.record, w.model->id(),
                                                     layers.has_value());
            provenance["from"] = w.origin;
            provenance["params"] = params;
            provenance["gamut"] = to_string(context.request.gamut);
            provenance["out_of_gamut"] = w.gamut;
            provenance["f0"] = Json::array({base.f0.r, base.f0.g, base.f0.b});
            provenance["base_color_factor"] = base.adjustment.empty()
                                                  ? std::string("F0 of the curve (the model at mu = 1)")
                                                  : "F0 of the curve (the model at mu = 1); " + base.adjustment;
            provenance["f82_tint"] = tint;
            provenance["f82_tint_note"] =
                "not in the material: KHR_materials_specular's specularColorFactor tints the "
                "dielectric F0 only and leaves the metal BRDF (Schlick from baseColor to 1) as "
                "it is, so glTF metals have no F82 tint";
            provenance["roughness"] = context.request.roughness;
            // The error figures of what a viewer draws (the core BRDF's Schlick from baseColorFactor), next to those
            // of the curve the params describe; a layered material's viewer curve is under glTF's own layers, which
            // metalfit does not evaluate.
            if (layers) {
                provenance["metrics"] = nullptr;
                provenance["metrics_of"] = "not evaluated: the viewer layers glTF's clearcoat and iridescence over "
                                           "baseColorFactor";
            } else {
                provenance["metrics"] =
                    metrics_record(gltf_curve(bare, bare.models[i], context.request.gamut).rendered->metrics);
                provenance["metrics_of"] = kGltfViewerCurve;
            }
            provenance["model_metrics"] = metrics_record(mt);
            Json extensions = Json::object();
            Json used = Json::array();
            if (layers) {
                provenance["layers"] = {{"base", "the bare metal's fit (" + bare.fit->material.name +
                                                     ", no layers): f0, params and metrics are its"},
                                        {"index_at_nm", kLayerIndexWavelengthNm},
                                        {"notes", layered_notes(*layers, ExportFormat::gltf)}};
                if (layers->coat) {  // a smooth coat; glTF fixes its index at 1.5 (the notes say what that changes)
                    extensions["KHR_materials_clearcoat"] = {{"clearcoatFactor", 1.0},
                                                             {"clearcoatRoughnessFactor", 0.0}};
                    used.push_back("KHR_materials_clearcoat");
                }
                if (layers->film) {  // one thickness: minimum = maximum (no thickness texture), in nanometres
                    extensions["KHR_materials_iridescence"] = {
                        {"iridescenceFactor", 1.0},
                        {"iridescenceIor", layers->film_ior},
                        {"iridescenceThicknessMinimum", layers->film_thickness_nm},
                        {"iridescenceThicknessMaximum", layers->film_thickness_nm}};
                    used.push_back("KHR_materials_iridescence");
                }
            }
            const std::size_t vertex_bytes = mesh.positions_bytes;
            Json j = {
                {"asset", {{"version", "2.0"}, {"generator", "metalfit " METALFIT_VERSION}}},
                {"scene", 0},
                {"scenes", Json::array({{{"name", stem}, {"nodes", Json::array({0})}}})},
                {"nodes", Json::array({{{"name", stem}, {"mesh", 0}}})},
                {"meshes", Json::array({{{"name", stem + "_sphere"},
                                         {"primitives", Json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                                                                      {"indices", 2},
                                                                      {"material", 0},
                                                                      {"mode", 4}}})}}})},
                {"materials",
                 Json::array({{{"name", stem},
                               {"pbrMetallicRoughness",
                                {{"baseColorFactor", Json::array({base.factor.r, base.factor.g, base.factor.b, 1.0})},
                                 {"metallicFactor", 1.0},
                                 {"roughnessFactor", context.request.roughness}}},
                               {"extras", {{"metalfit", provenance}}}}})},
                {"accessors",
                 Json::array(
                     {{{"bufferView", 0},
                       {"componentType", 5126},
                       {"count", mesh.vertices.size()},
                       {"type", "VEC3"},
                       {"min", vec3_json(mesh.min)},
                       {"max", vec3_json(mesh.max)}},
                      {{"bufferView", 1}, {"componentType", 5126}, {"count", mesh.vertices.size()}, {"type", "VEC3"}},
                      {{"bufferView", 2},
                       {"componentType", 5123},
                       {"count", mesh.indices.size()},
                       {"type", "SCALAR"}}})},
                {"bufferViews",
                 Json::array(
                     {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vertex_bytes}, {"target", 34962}},
                      {{"buffer", 0}, {"byteOffset", vertex_bytes}, {"byteLength", vertex_bytes}, {"target", 34962}},
                      {{"buffer", 0},
                       {"byteOffset", 2 * vertex_bytes},
                       {"byteLength", mesh.indices_bytes},
                       {"target", 34963}}})},
                {"buffers", Json::array({{{"byteLength", mesh.buffer.size()}, {"uri", uri}}})}};
            if (!used.empty()) {
                j["extensionsUsed"] = used;
                j["materials"][0]["extensions"] = extensions;
            }
            files.push_back({"gltf/" + stem + ".gltf", j.dump(2) + "\n"});
        }
    return files;
}

ConsumerCurve gltf_curve(const MaterialExport& material, const ModelExport& model, GamutPolicy gamut) {
    const GltfBaseColor base = gltf_base_color(model.written, gamut);
    WrittenParameters w;
    w.model = &find_model("schlick");
    w.origin = "baseColorFactor, the F0 of " + std::string(model.written.model->id()) + "'s curve";
    for (int c = 0; c < 3; ++c) w.params[c] = {base.factor[c]};
    if (!base.adjustment.empty()) w.gamut.push_back(base.adjustment);
    w.metrics = compute_metrics(*w.model, w.params, *material.fit->reference);
    return {ExportFormat::gltf, kGltfViewerCurve, std::move(w), ""};
}

}  // namespace metalfit::detail
