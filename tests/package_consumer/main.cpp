// A program outside metalfit's tree: loads the built-in catalog from wherever default_data_dir() finds it, fits
// gold with the f82-tint model and prints what it used and got, one value per line ("key c value").
#include <cstdio>
#include <iostream>

#include "libfit/base/data_dir.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/version.hpp"
#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/io/catalog.hpp"

int main() {
    using namespace metalfit;
    try {
        const std::filesystem::path data = default_data_dir();
        const Catalog catalog = Catalog::load(data);
        const Material gold = load_material(catalog, "gold");
        const Colorimetry colorimetry = Colorimetry::load(data, Observer::cie1931_2deg, Illuminant::D65);
        const ColorSpaceConverter converter = ColorSpaceConverter::create(choose_ocio_config(std::nullopt, data));
        const MaterialFitRequest request{{}, {}, {&find_model("f82-tint")}};
        const MaterialFit fit = fit_material(gold, colorimetry, converter, request);

        std::cout << "version " << METALFIT_VERSION << "\n"
                  << "data_dir " << data.string() << "\n";
        const ModelParameters& p = fit.models.at(0).fit.value.params;
        const RGB F0 = p.parameter(0), tint = p.parameter(1);
        for (int c = 0; c < 3; ++c) {
            char line[128];
            std::snprintf(line, sizeof line, "F0 %d %.17g\nfit_F0 %d %.17g\nfit_tint %d %.17g\n", c, fit.F0[c], c,
                          F0[c], c, tint[c]);
            std::cout << line;
        }
        return 0;
    } catch (...) {
        return report_current_exception("consumer");
    }
}
