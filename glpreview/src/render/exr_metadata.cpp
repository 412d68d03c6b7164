#include "glpreview/render/exr_metadata.hpp"

#include "libfit/base/number_text.hpp"
#include "libfit/base/version.hpp"

namespace metalfit::glpreview {
namespace {

std::string parameters_text(const SphereFresnel& f) {
    std::string out;
    const auto names = f.model->parameters();
    for (std::size_t i = 0; i < names.size(); ++i) {
        const RGB v = f.parameters.parameter(i);
        out += (i ? "; " : "") + std::string(names[i].name) + " = (" + significant_text(v.r, 9) + ", " +
               significant_text(v.g, 9) + ", " + significant_text(v.b, 9) + ")";
    }
    return out;
}

}  // namespace

ExrMetadata sphere_metadata(const Scene& scene, const std::vector<const SphereFresnel*>& fresnel) {
    ExrMetadata m{{"metalfit/scene", scene.file.filename().string()},
                  {"metalfit/spheres", static_cast<int>(scene.spheres.size())}};
    for (std::size_t i = 0; i < scene.spheres.size() && i < fresnel.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const SphereFresnel& f = *fresnel[i];
        const std::string at = "metalfit/sphere" + std::to_string(i) + "/";
        m.push_back({at + "material", s.material});
        m.push_back({at + "name", f.material});
        m.push_back({at + "source", f.source});
        m.push_back({at + "model", f.fresnel});
        if (f.model) {
            m.push_back({at + "params", std::string(f.params ? to_string(*f.params) : "fit")});
            m.push_back({at + "parameters", parameters_text(f)});
        }
        m.push_back({at + "roughness", static_cast<float>(s.roughness)});
        m.push_back({at + "reflection", std::string(to_string(s.reflection))});
    }
    return m;
}

ExrMetadata image_metadata(ExrMetadata metadata, const std::string& file) {
    metadata.insert(metadata.begin(), {{"metalfit/version", std::string(METALFIT_VERSION)}, {"metalfit/image", file}});
    return metadata;
}

}  // namespace metalfit::glpreview
