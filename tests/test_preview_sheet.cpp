// glpreview's QA sheet (issue 17 item 7): the column layout, the labels drawn with OpenImageIO (where, and nowhere
// else), --sheet-models / --sheet-roughness / --sheet-labels on the command line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "glpreview/io/image_io.hpp"
#include "glpreview/io/image_text.hpp"
#include "glpreview/render/sheet_layout.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::test {
namespace {

using namespace metalfit::glpreview;

CommandResult glpreview(const std::string& arguments, const TempDir& dir) {
    return run_command(kGlpreviewExe, arguments, dir.path());
}

// The shipped sheet room, small.
std::string sheet_scene() { return (kData / "scenes" / "sheet.json").string(); }
constexpr int kCell = 96;
const std::string kSize = " --size 96x96";

TEST(SheetLayout, OneColumnGroupPerModelWithEveryRoughness) {
    const std::vector<SheetColumn> columns = sheet_columns(3, 2);
    ASSERT_EQ(columns.size(), 2u + 3u * 2u * 2u);
    int reference = 0;
    std::map<int, int> per_group;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const SheetColumn& col = columns[c];
        EXPECT_EQ(sheet_column(col.kind, col.group, col.roughness, 2), static_cast<int>(c));
        if (col.kind == SheetCellKind::reference)
            ++reference;
        else
            ++per_group[col.group];
    }
    EXPECT_EQ(reference, 2);
    ASSERT_EQ(per_group.size(), 3u);
    for (const auto& [group, count] : per_group) EXPECT_EQ(count, 4) << "group " << group;
    // Today's sheet: reference | model | difference.
    const std::vector<SheetColumn> plain = sheet_columns(1, 1);
    ASSERT_EQ(plain.size(), 3u);
    EXPECT_EQ(plain[0].kind, SheetCellKind::reference);
    EXPECT_EQ(plain[1].kind, SheetCellKind::model);
    EXPECT_EQ(plain[2].kind, SheetCellKind::difference);
}

TEST(SheetLayout, BadRequestsAreUsageErrorsNamingTheOption) {
    auto message = [](const SheetRequest& r) -> std::string {
        try {
            check_sheet_request(r);
        } catch (const UsageError& e) {
            return e.what();
        }
        return {};
    };
    EXPECT_TRUE(Contains(message({{"Au"}, {"f82-tint", "no-such-model"}, {}}),
                         "--sheet-models: unknown model 'no-such-model'"));
    EXPECT_TRUE(Contains(message({{"Au"}, {"schlick", "schlick"}, {}}), "named twice"));
    EXPECT_TRUE(Contains(message({{"Au"}, {}, {0.0, 1.5}}), "--sheet-roughness"));
    EXPECT_TRUE(Contains(message({{"Au"}, {}, {0.2, 0.2}}), "--sheet-roughness"));
    EXPECT_EQ(message({{"Au"}, {"schlick", "f82-tint"}, {0.0, 0.2, 0.5}}), "");
}

TEST(SheetLayout, LabelsSayMaterialModelRoughnessAndErrorInsideTheirCellsBands) {
    const std::vector<SheetCell> cells{{0, 0, SheetCellKind::reference, "gold", "", 0.2, 0},
                                       {1, 3, SheetCellKind::model, "zinc", "f82-tint", 0.5, 0.0123},
                                       {1, 4, SheetCellKind::difference, "zinc", "f82-tint", 0.5, 0.00031}};
    const std::vector<TextBox> boxes = sheet_labels(cells, 100, 80);
    ASSERT_EQ(boxes.size(), 6u);
    EXPECT_EQ(boxes[0].text, "gold: reference");
    EXPECT_EQ(boxes[1].text, "roughness 0.2");
    EXPECT_EQ(boxes[2].text, "zinc: f82-tint");
    EXPECT_EQ(boxes[3].text, "roughness 0.5, rel_rms 1.2%");
    EXPECT_EQ(boxes[4].text, "|f82-tint - ref| x 10");
    EXPECT_EQ(boxes[5].text, "roughness 0.5, RMSE 0.00031");
    const int band = label_band_height(80);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const SheetCell& c = cells[i / 2];
        EXPECT_EQ(boxes[i].x, c.column * 100);
        EXPECT_EQ(boxes[i].width, 100);
        EXPECT_EQ(boxes[i].height, band);
        EXPECT_EQ(boxes[i].y, i % 2 == 0 ? c.row * 80 : c.row * 80 + 80 - band);
    }
}

TEST(ImageText, DrawsInsideItsBoxAndNowhereElse) {
    Image image(120, 60);
    for (float& v : image.rgb) v = 0.25f;
    const Image before = image;
    draw_text(image, {{10, 20, 70, 16, "gold: f82-tint, a label too long for its box", 12}});
    int inside = 0, outside = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const bool changed = image.at(x, y).r != before.at(x, y).r || image.at(x, y).g != before.at(x, y).g;
            const bool in_box = x >= 10 && x < 80 && y >= 20 && y < 36;
            (in_box ? inside : outside) += changed ? 1 : 0;
        }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(inside, 40) << "text drawn";
    EXPECT_LT(inside, 70 * 16) << "glyphs, not a filled box";
}

// Pixels of two 8-bit images that differ, split by whether they lie in a label band of the sheet's cells.
struct Changes {
    long in_bands = 0, outside_bands = 0, band_pixels = 0;
};
Changes changes_by_band(const Png8& a, const Png8& b, int cell) {
    Changes c;
    const int band = label_band_height(cell);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const int in_cell = y % cell;
            const bool in_band = in_cell < band || in_cell >= cell - band;
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * a.width + x);
            const bool changed = a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
            if (in_band) ++c.band_pixels;
            (in_band ? c.in_bands : c.outside_bands) += changed ? 1 : 0;
        }
    return c;
}

TEST(PreviewSheet, LabelsChangeOnlyTheLabelBandsOfThePng) {
    TempDir dir;
    const std::string common = sheet_scene() + " --sheet Au,Zn --sheet-models f82-tint,schlick" + kSize;
    const CommandResult labelled = glpreview(common + " -o " + (dir.path() / "on").string(), dir);
    ASSERT_EQ(labelled.exit_code, 0) << labelled.err;
    const CommandResult bare = glpreview(common + " --sheet-labels off -o " + (dir.path() / "off").string(), dir);
    ASSERT_EQ(bare.exit_code, 0) << bare.err;
    const Png8 on = read_png8(dir.path() / "on" / "sheet.png"), off = read_png8(dir.path() / "off" / "sheet.png");
    ASSERT_EQ(on.width, off.width);
    ASSERT_EQ(on.height, off.height);
    EXPECT_EQ(on.width, 5 * kCell);  // reference | f82-tint, |diff| | schlick, |diff|
    EXPECT_EQ(on.height, 2 * kCell);
    const Changes c = changes_by_band(on, off, kCell);
    EXPECT_EQ(c.outside_bands, 0);
    EXPECT_GT(c.in_bands, 20 * 10) << "every cell has its text (10 cells)";
    EXPECT_LT(c.in_bands, c.band_pixels / 2) << "text, not filled bands";
    // Each cell's label is its own: the two model cells of a row differ in their top band.
    long differing = 0;
    const int band = label_band_height(kCell);
    for (int y = 0; y < band; ++y)
        for (int x = 0; x < kCell; ++x) {
            const std::size_t a = 3 * (static_cast<std::size_t>(y) * on.width + 1 * kCell + x);
            const std::size_t b = 3 * (static_cast<std::size_t>(y) * on.width + 3 * kCell + x);
            differing += on.rgb[a] != on.rgb[b];
        }
    EXPECT_GT(differing, 10) << "'gold: f82-tint' and 'gold: schlick' look alike";
    // The EXR holds the renders only, labelled or not.
    const Image exr_on = read_image(dir.path() / "on" / "sheet.exr"),
                exr_off = read_image(dir.path() / "off" / "sheet.exr");
    EXPECT_EQ(exr_on.rgb, exr_off.rgb);
}

TEST(PreviewSheet, OneColumnGroupPerModelAndOneColumnPerRoughness) {
    TempDir dir;
    const CommandResult run = glpreview(sheet_scene() +
                                            " --sheet Au,Cu --sheet-models f82-tint,schlick,conductor-rgb "
                                            "--sheet-roughness 0,0.5 --sheet-labels off" +
                                            kSize + " -o " + (dir.path() / "out").string(),
                                        dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto record = nlohmann::json::parse(read_file(dir.path() / "out" / "sheet.json"));
    ASSERT_EQ(record.size(), 2u * 3u * 2u);
    const Image sheet = read_image(dir.path() / "out" / "sheet.exr");
    EXPECT_EQ(sheet.width, (2 + 3 * 2 * 2) * kCell);
    EXPECT_EQ(sheet.height, 2 * kCell);
    std::set<int> columns;
    const std::vector<std::string> models{"f82-tint", "schlick", "conductor-rgb"};
    for (std::size_t i = 0; i < record.size(); ++i) {
        const auto& e = record[i];
        EXPECT_EQ(e["row"], i / 6);
        EXPECT_EQ(e["model"], models[(i / 2) % 3]);
        EXPECT_EQ(e["roughness"].get<double>(), i % 2 == 0 ? 0.0 : 0.5);
        EXPECT_EQ(e["columns"]["reference"], i % 2);
        EXPECT_EQ(e["columns"]["difference"].get<int>(), e["columns"]["model"].get<int>() + 1);
        if (e["row"] == 0) {
            columns.insert(e["columns"]["model"].get<int>());
            columns.insert(e["columns"]["difference"].get<int>());
        }
    }
    EXPECT_EQ(columns.size(), 12u) << "every model cell and difference cell has a column of its own";
    // A rough cell is not the mirror: the reference at 0.5 differs from the one at 0.
    double squared = 0;
    for (int y = 0; y < kCell; ++y)
        for (int x = 0; x < kCell; ++x) {
            const RGB a = sheet.at(x, y), b = sheet.at(kCell + x, y);
            squared += (a.g - b.g) * (a.g - b.g);
        }
    EXPECT_GT(squared / (kCell * kCell), 1e-4);
}

TEST(PreviewSheet, TheRoughnessZeroColumnsAreTodaysSheet) {
    TempDir dir;
    const std::string common = sheet_scene() + " --sheet Au --sheet-models f82-tint --sheet-labels off" + kSize;
    ASSERT_EQ(glpreview(common + " -o " + (dir.path() / "mirror").string(), dir).exit_code, 0);
    const CommandResult rough =
        glpreview(common + " --sheet-roughness 0,0.2 -o " + (dir.path() / "rough").string(), dir);
    ASSERT_EQ(rough.exit_code, 0) << rough.err;
    const Image mirror = read_image(dir.path() / "mirror" / "sheet.exr"),
                both = read_image(dir.path() / "rough" / "sheet.exr");
    ASSERT_EQ(mirror.width, 3 * kCell);
    ASSERT_EQ(both.width, 6 * kCell);
    // mirror: reference | f82-tint | diff; rough: ref 0 | ref 0.2 | f82-tint 0 | diff 0 | f82-tint 0.2 | diff 0.2.
    for (const auto& [from, to] : std::vector<std::pair<int, int>>{{0, 0}, {1, 2}, {2, 3}})
        for (int y = 0; y < kCell; ++y)
            for (int x = 0; x < kCell; ++x) {
                const RGB a = mirror.at(from * kCell + x, y), b = both.at(to * kCell + x, y);
                ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b) << "column " << from << " pixel " << x << "," << y;
            }
}

TEST(PreviewSheet, UnknownModelOrBadRoughnessIsAOneLineUsageError) {
    TempDir dir;
    const fs::path out = dir.path() / "out";
    for (const std::string& bad :
         {std::string(" --sheet Au --sheet-models f82-tint,no-such-model"),
          std::string(" --sheet Au --sheet-roughness 0,2"), std::string(" --sheet Au --sheet-roughness 0,rough"),
          std::string(" --sheet-models schlick"), std::string(" --sheet Au --sheet-labels maybe")}) {
        const CommandResult run = glpreview(sheet_scene() + bad + kSize + " -o " + out.string(), dir);
        EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << bad << ": " << run.err;
        EXPECT_TRUE(Contains(run.err, "--sheet")) << run.err;
        EXPECT_FALSE(fs::exists(out)) << bad;
    }
    const CommandResult unknown = glpreview(sheet_scene() + " --sheet Au --sheet-models no-such-model --explain", dir);
    EXPECT_TRUE(Contains(unknown.err, "unknown model 'no-such-model'")) << unknown.err;
}

TEST(PreviewSheet, ExplainShowsTheRoughPassesAndTheLabels) {
    TempDir dir;
    const CommandResult mirror = glpreview(sheet_scene() + " --sheet Au --explain", dir);
    ASSERT_EQ(mirror.exit_code, 0) << mirror.err;
    EXPECT_TRUE(Contains(mirror.out, "sheet-labels")) << mirror.out;
    EXPECT_TRUE(Contains(mirror.out, "prefilter-environment: no roughness column")) << mirror.out;
    const CommandResult rough =
        glpreview(sheet_scene() + " --sheet Au --sheet-roughness 0,0.5 --sheet-labels off --explain", dir);
    ASSERT_EQ(rough.exit_code, 0) << rough.err;
    EXPECT_TRUE(Contains(rough.out, "sheet-labels: --sheet-labels off")) << rough.out;
    EXPECT_TRUE(Contains(rough.out, "at roughness 0, 0.5")) << rough.out;
}

}  // namespace
}  // namespace metalfit::test
