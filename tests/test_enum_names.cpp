// The names of enum values (libfit/base/enum_names.hpp): one table per enum prints and parses, every value reads
// back, and an unknown name gets the message each option has always given.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "libfit/base/enum_names.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/color/chromatic_adaptation.hpp"
#include "libfit/color/colorimetry.hpp"
#include "libfit/color/convention.hpp"
#include "libfit/export/export.hpp"
#include "libfit/fit/budget.hpp"
#include "libfit/fit/parameter_source.hpp"
#include "libfit/reference/sampled_reference.hpp"
#include "libfit/report/sphere_renders.hpp"
#include "libfit/spectral/spectrum.hpp"

namespace test_enum_names {

using namespace metalfit;

std::string usage_message(const auto& call) {
    try {
        call();
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(no UsageError)";
}

// Every value once, every name once, and parse(name(v)) == v.
template <typename Table>
void expect_round_trip(const Table& table, std::size_t values) {
    EXPECT_EQ(table.names.size(), values) << table.what;
    std::set<std::string_view> names;
    std::set<int> seen;
    for (const auto& [value, name] : table.names) {
        EXPECT_TRUE(names.insert(name).second) << table.what << ": the name " << name << " twice";
        EXPECT_TRUE(seen.insert(static_cast<int>(value)).second) << table.what << ": a value named twice";
        EXPECT_EQ(table.name(value), name);
        EXPECT_EQ(table.parse(table.name(value)), value) << name;
        EXPECT_EQ(table.find(name), value);
    }
    EXPECT_FALSE(table.find("")) << table.what;
    EXPECT_FALSE(table.find("no-such-name")) << table.what;
}

TEST(EnumNames, EveryValueOfEveryTableReadsBack) {
    expect_round_trip(kBudgetMetricNames, 4);
    expect_round_trip(kRenderModeNames, 3);
    expect_round_trip(kErrorMetricNames, 2);
    expect_round_trip(kAngularWeightNames, 2);
    expect_round_trip(kConventionNames, 3);
    expect_round_trip(kObserverNames, 4);
    expect_round_trip(kAdaptationNames, 4);
    expect_round_trip(kInterpolationNames, 2);
    expect_round_trip(kOutOfRangeNames, 2);
    expect_round_trip(kParameterSourceNames, 2);
    expect_round_trip(kGamutPolicyNames, 3);
    expect_round_trip(kExportFormatNames, 10);
}

TEST(EnumNames, ThePrintingFunctionsUseTheTables) {
    EXPECT_EQ(to_string(BudgetMetric::de2000_max), "de2000_max");
    EXPECT_EQ(to_string(ErrorMetric::abs), "abs");
    EXPECT_EQ(to_string(AngularWeight::cosine), "cosine");
    EXPECT_EQ(to_string(Convention::physicallybased), "physicallybased");
    EXPECT_EQ(option_name(Observer::cie2015_10deg), "2015-10");
    EXPECT_EQ(to_string(Observer::cie2015_10deg), "CIE 2015 10°");  // the title, not the option's name
    EXPECT_EQ(to_string(Adaptation::von_kries_xyz), "von-kries-xyz");
    EXPECT_EQ(to_string(Interpolation::pchip), "pchip");
    EXPECT_EQ(to_string(OutOfRange::clamp), "clamp");
    EXPECT_EQ(to_string(ParameterSource::closed), "closed");
    EXPECT_EQ(to_string(GamutPolicy::scale), "scale");
    EXPECT_EQ(to_string(ExportFormat::openpbr), "openpbr");
    EXPECT_EQ(parse_observer("1964"), Observer::cie1964_10deg);
    EXPECT_EQ(parse_render_mode("auto"), RenderMode::auto_);
}

TEST(EnumNames, NamesAreExact) {
    EXPECT_THROW(parse_gamut_policy("Keep"), UsageError);
    EXPECT_THROW(parse_gamut_policy("keep "), UsageError);
    EXPECT_THROW(parse_adaptation("von_kries_xyz"), UsageError);
}

TEST(EnumNames, AnUnknownNameGetsTheMessageItAlwaysGot) {
    // Each the exact text the hand-written parser of that option printed.
    EXPECT_EQ(usage_message([] { parse_budget_metric("rms"); }),
              "unknown budget metric 'rms' (known: rel_rms, max_rel, de2000_max, f0_err)");
    EXPECT_EQ(usage_message([] { parse_render_mode("yes"); }), "unknown --renders mode 'yes' (auto, on or off)");
    EXPECT_EQ(usage_message([] { parse_error_metric("rmse"); }), "unknown error metric 'rmse' (known: rel, abs)");
    EXPECT_EQ(usage_message([] { parse_angular_weight("flat"); }),
              "unknown angular weight 'flat' (known: uniform, cosine)");
    EXPECT_EQ(usage_message([] { parse_convention("pbr"); }),
              "unknown convention 'pbr' (expected metalfit, adobe or physicallybased)");
    EXPECT_EQ(usage_message([] { parse_observer("1932"); }),
              "unknown observer '1932' (expected 1931, 1964, 2015-2 or 2015-10)");
    EXPECT_EQ(usage_message([] { parse_adaptation("cat16"); }),
              "unknown chromatic adaptation 'cat16' (expected bradford, cat02, von-kries-xyz or none)");
    EXPECT_EQ(usage_message([] { parse_parameter_source("best"); }), "unknown parameter source 'best' (fit or closed)");
    EXPECT_EQ(usage_message([] { parse_gamut_policy("wrap"); }), "unknown gamut policy 'wrap' (keep, clip or scale)");
    EXPECT_EQ(kExportFormatNames.known(), "known: json, glsl, hlsl, mtlx, openpbr, cpp, gltf, blender, msl, wgsl");
}

TEST(EnumNames, TheKnownNamesWordings) {
    enum class Two { a, b };
    constexpr EnumNames one{"thing", KnownNamesWording::alternatives, std::array{EnumName<Two>{Two::a, "a"}}};
    EXPECT_EQ(one.known(), "a");
    constexpr EnumNames two{"thing", KnownNamesWording::expected,
                            std::array{EnumName<Two>{Two::a, "a"}, EnumName<Two>{Two::b, "b"}}};
    EXPECT_EQ(two.known(), "expected a or b");
    EXPECT_EQ(usage_message([&] { two.parse("c"); }), "unknown thing 'c' (expected a or b)");
    static_assert(two.find("b") == Two::b);  // a table is usable at compile time
    static_assert(two.name(Two::a) == "a");
}

}  // namespace test_enum_names
