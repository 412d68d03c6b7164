// The colour set-up the fit, export and report tests share: the built-in catalog, CIE 1931 2° under D65 and the
// shipped OCIO config's scene_linear (Linear Rec.709), made once per test program.
#pragma once

#include "libfit/color/color_space.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/fit/fit_batch.hpp"
#include "libfit/fit/fit_record.hpp"
#include "libfit/io/catalog.hpp"
#include "test_support.hpp"

namespace metalfit::test {

inline const OcioConfigChoice kShipped{kData / "ocio" / "config.ocio", "test"};

struct Environment {
    Catalog catalog = Catalog::load(kData);
    Colorimetry colorimetry = Colorimetry::load(kData, Observer::cie1931_2deg, Illuminant::D65);
    ColorSpaceConverter converter = ColorSpaceConverter::create(kShipped);
    // What fit_materials_in_order takes, and the record's context, for this set-up (`metalfit fit`'s defaults).
    BatchColour colour() const { return {kShipped, colorimetry, converter}; }
    FitRecordContext context() const {
        FitRecordContext c{kShipped, converter.space(), Observer::cie1931_2deg, Illuminant::D65, {}, {}};
        c.data_dir = kData;
        return c;
    }
};

inline const Environment& env() {
    static const Environment e;
    return e;
}

}  // namespace metalfit::test
