// glpreview's QA sheet (issue 17 item 7): the column layout, the labels drawn with OpenImageIO (where, and nowhere
// else), --sheet-models / --sheet-roughness / --sheet-labels on the command line.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "glpreview/io/image_io.hpp"
#include "glpreview/io/image_text.hpp"
#include "glpreview/render/preview_passes.hpp"
#include "glpreview/render/sheet_layout.hpp"
#include "libfit/base/errors.hpp"
#include "test_support.hpp"

namespace metalfit::test {
namespace test_preview_sheet {

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
    EXPECT_TRUE(Contains(message({{"Au"}, {"best", "f82-tint", "best"}, {}}), "model 'best' named twice"));
    EXPECT_EQ(message({{"Au"}, {"best", "f82-tint", "schlick"}, {}}), "");
}

TEST(SheetLayout, LabelsSayMaterialModelRoughnessAndErrorInsideTheirCellsBands) {
    const std::vector<SheetCell> cells{{0, 0, SheetCellKind::reference, "gold", "", 0.2, 0},
                                       {1, 3, SheetCellKind::model, "zinc", "f82-tint", 0.5, 0.0123},
                                       {1, 4, SheetCellKind::difference, "zinc", "f82-tint", 0.5, 0.00031},
                                       {1, 5, SheetCellKind::model, "zinc", "schlick", 0.5, 0.02, false, true}};
    const std::vector<TextBox> boxes = sheet_labels(cells, 100, 80, ErrorScale{1e-5, 0.1});
    ASSERT_EQ(boxes.size(), 8u);
    EXPECT_EQ(boxes[0].text, "gold: reference");
    EXPECT_EQ(boxes[1].text, "roughness 0.2");
    EXPECT_EQ(boxes[2].text, "zinc: f82-tint");
    EXPECT_EQ(boxes[3].text, "roughness 0.5, rel_rms 1.2%");
    EXPECT_EQ(boxes[4].text, "f82-tint / ref - 1");
    EXPECT_EQ(boxes[5].text, "roughness 0.5, +-1e-05..0.1 log");
    EXPECT_EQ(boxes[6].text, "zinc: schlick (best)");
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

// The cell (column, row) of an image made of kCell × kCell cells, as a standalone image.
Image cell_of(const Image& sheet, int column, int row) {
    Image cell(kCell, kCell);
    for (int y = 0; y < kCell; ++y)
        for (int x = 0; x < kCell; ++x) cell.set(x, y, sheet.at(column * kCell + x, row * kCell + y));
    return cell;
}

TEST(PreviewSheet, BestStandsBesideNamedModels) {
    TempDir dir;
    const std::string common = sheet_scene() + " --sheet Au,Cu --sheet-labels off" + kSize;
    const CommandResult alone = glpreview(common + " -o " + (dir.path() / "best").string(), dir);
    ASSERT_EQ(alone.exit_code, 0) << alone.err;
    const CommandResult both =
        glpreview(common + " --sheet-models best,f82-tint -o " + (dir.path() / "both").string(), dir);
    ASSERT_EQ(both.exit_code, 0) << both.err;
    const auto best = nlohmann::json::parse(read_file(dir.path() / "best" / "sheet.json"));
    const auto record = nlohmann::json::parse(read_file(dir.path() / "both" / "sheet.json"));
    ASSERT_EQ(best.size(), 2u);
    ASSERT_EQ(record.size(), 4u);  // two rows × {best, f82-tint}
    const Image best_sheet = read_image(dir.path() / "best" / "sheet.exr"),
                both_sheet = read_image(dir.path() / "both" / "sheet.exr");
    for (int row = 0; row < 2; ++row) {
        EXPECT_EQ(record[2 * row]["asked_for"], "best");
        EXPECT_EQ(record[2 * row]["model"], best[row]["model"]) << "the same model as --sheet-models best";
        EXPECT_EQ(record[2 * row + 1]["asked_for"], "f82-tint");
        EXPECT_EQ(record[2 * row + 1]["model"], "f82-tint");
        // The best group's cells are those of the best-only sheet (reference | model | difference).
        for (int column = 0; column < 3; ++column)
            EXPECT_EQ(cell_of(both_sheet, column, row).rgb, cell_of(best_sheet, column, row).rgb)
                << "row " << row << " column " << column;
    }
}

// A PNG pixel as linear-ish numbers (the display transform keeps each channel's order).
struct Pixel8 {
    int r, g, b;
};
Pixel8 png_at(const Png8& png, int x, int y) {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * png.width + x);
    return {png.rgb[i], png.rgb[i + 1], png.rgb[i + 2]};
}

// Rec. 709 luminance (the sheet scene's space is linear Rec. 709), computed here apart from the view's OCIO path.
double luminance_709(const RGB& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

TEST(PreviewSheet, ThePngShowsEachModelsSignedErrorInFalseColour) {
    TempDir dir;
    const std::string common = sheet_scene() + " --sheet Au,Ag --sheet-models best,schlick --sheet-labels off" + kSize;
    ASSERT_EQ(glpreview(common + " -o " + (dir.path() / "out").string(), dir).exit_code, 0);
    const CommandResult dark = glpreview(common + " --exposure=-3 -o " + (dir.path() / "dark").string(), dir);
    ASSERT_EQ(dark.exit_code, 0) << dark.err;
    // sheet.exr (half floats: about 5e-4 relative) holds the renders and |model - reference| x 10.
    const Image sheet = read_image(dir.path() / "out" / "sheet.exr");
    const Png8 png = read_png8(dir.path() / "out" / "sheet.png"),
               dark_png = read_png8(dir.path() / "dark" / "sheet.png");
    ASSERT_EQ(png.width, sheet.width);
    const int band = label_band_height(kCell);
    const CellRect bar = colour_bar_rect(0, 0, kCell, kCell);
    long warm = 0, cold = 0, wrong = 0, black_where_equal = 0, equal = 0, small_and_shown = 0, small = 0;
    long darker_references = 0, references = 0, same_views = 0, views = 0;
    for (int row = 0; row < 2; ++row)
        for (int group = 0; group < 2; ++group) {
            const int model_column = 1 + 2 * group, difference_column = model_column + 1;
            for (int y = band; y < kCell - band; ++y)
                for (int x = 0; x < bar.x; ++x) {
                    const int py = row * kCell + y;
                    const RGB m = sheet.at(model_column * kCell + x, py), r = sheet.at(x, py);
                    const RGB delta = sheet.at(difference_column * kCell + x, py);
                    const Pixel8 p = png_at(png, difference_column * kCell + x, py);
                    const Pixel8 q = png_at(dark_png, difference_column * kCell + x, py);
                    ++views;
                    same_views += p.r == q.r && p.g == q.g && p.b == q.b;
                    const Pixel8 ref = png_at(png, x, py), ref_dark = png_at(dark_png, x, py);
                    if (ref.r + ref.g + ref.b > 30) {
                        ++references;
                        darker_references += ref_dark.r + ref_dark.g + ref_dark.b < ref.r + ref.g + ref.b;
                    }
                    if (delta.r == 0 && delta.g == 0 && delta.b == 0) {  // model and reference equal as floats
                        ++equal;
                        black_where_equal += p.r + p.g + p.b == 0;
                        continue;
                    }
                    if (luminance_709(r) < 1e-3) continue;
                    const double e = luminance_709(m) / luminance_709(r) - 1;
                    if (e > 4e-3) (p.r > p.b ? warm : wrong) += 1;   // the model brighter: warm
                    if (e < -4e-3) (p.b > p.r ? cold : wrong) += 1;  // darker: cold
                    if (std::abs(e) > 1.5e-3 && std::abs(e) < 4e-3) {
                        ++small;
                        small_and_shown += p.r + p.g + p.b > 24;
                    }
                }
        }
    EXPECT_GT(equal, 1000) << "the room around the sphere";
    EXPECT_EQ(black_where_equal, equal) << "no error: black";
    EXPECT_GT(warm, 50);
    EXPECT_GT(cold, 50);
    EXPECT_EQ(wrong, 0) << "warm where the model is brighter, cold where darker";
    EXPECT_GT(small, 50);
    EXPECT_EQ(small_and_shown, small) << "errors of 0.15-0.4 % are plainly coloured";
    EXPECT_EQ(same_views, views) << "the error views do not change with the exposure";
    EXPECT_GT(darker_references, references * 9 / 10) << "the renders do";
}

TEST(PreviewSheet, ExposureChangesThePngsOnlyAndANonFiniteOneIsRefused) {
    TempDir dir;
    const std::string scene = sheet_scene() + kSize;
    ASSERT_EQ(glpreview(scene + " -o " + (dir.path() / "a").string(), dir).exit_code, 0);
    const CommandResult darker = glpreview(scene + " --exposure=-2 -o " + (dir.path() / "b").string(), dir);
    ASSERT_EQ(darker.exit_code, 0) << darker.err;
    EXPECT_TRUE(read_image(dir.path() / "a" / "beauty.exr").rgb == read_image(dir.path() / "b" / "beauty.exr").rgb);
    const Png8 a = read_png8(dir.path() / "a" / "beauty.png"), b = read_png8(dir.path() / "b" / "beauty.png");
    long sum_a = 0, sum_b = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        sum_a += a.rgb[i];
        sum_b += b.rgb[i];
    }
    EXPECT_LT(sum_b, sum_a * 3 / 4);
    for (const std::string bad : {"nan", "inf", "-inf", "1e9", "two", "-33"}) {
        const fs::path out = dir.path() / "bad";
        const CommandResult run = glpreview(scene + " '--exposure=" + bad + "' -o " + out.string(), dir);
        EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << bad << ": " << run.err;
        EXPECT_TRUE(Contains(run.err, "--exposure")) << run.err;
        EXPECT_FALSE(fs::exists(out)) << bad;
    }
}

// A scene's PNGs say what they show in a top band (outputs.labels); nothing else of them changes, nor the EXRs.
TEST(PreviewSheet, AScenesPngsCarryTheirCaptionInTheTopBandOnly) {
    TempDir dir;
    const std::string scene_text = R"({"image": {"width": 96, "height": 64},
        "spheres": [{"center": [0, 1, 0], "radius": 0.5, "material": "Cu", "fresnel": "schlick"}], "outputs": )";
    const fs::path on = dir.write("on.json", scene_text + R"({"labels": true}})");
    const fs::path off = dir.write("off.json", scene_text + "{}}");  // the default: no captions
    ASSERT_EQ(glpreview(on.string() + " -o " + (dir.path() / "on").string(), dir).exit_code, 0);
    ASSERT_EQ(glpreview(off.string() + " -o " + (dir.path() / "off").string(), dir).exit_code, 0);
    const int band = caption_band_height(64);
    for (const char* file : {"beauty.png", "reference.png", "difference.png"}) {
        const Png8 a = read_png8(dir.path() / "on" / file), b = read_png8(dir.path() / "off" / file);
        ASSERT_EQ(a.rgb.size(), b.rgb.size());
        long in_band = 0, outside = 0;
        for (std::size_t i = 0; i < a.rgb.size(); ++i)
            if (a.rgb[i] != b.rgb[i]) (static_cast<int>(i / 3 / a.width) < band ? in_band : outside) += 1;
        EXPECT_EQ(outside, 0) << file;
        EXPECT_GT(in_band, 30) << file << ": the caption is drawn";
    }
    for (const char* file : {"beauty.exr", "reference.exr", "difference.exr"})
        EXPECT_TRUE(read_image(dir.path() / "on" / file).rgb == read_image(dir.path() / "off" / file).rgb) << file;
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

// --sheet-progress: a line per row, in order, before the sheet's own output; without it and off a terminal, none
// (issue 29 item 6: metalfit report relays these as its progress).
TEST(PreviewSheet, SheetProgressIsALinePerRowInOrder) {
    TempDir dir;
    const std::string common = sheet_scene() + " --sheet Au,Cu,Ag --sheet-models schlick --sheet-labels off" + kSize;
    const CommandResult with = glpreview(common + " --sheet-progress -o " + (dir.path() / "with").string(), dir);
    ASSERT_EQ(with.exit_code, 0) << with.err;
    const std::size_t one = with.out.find("sheet-progress 1 3\n"), two = with.out.find("sheet-progress 2 3\n"),
                      three = with.out.find("sheet-progress 3 3\n"), png = with.out.find("sheet.png");
    ASSERT_NE(one, std::string::npos) << with.out;
    ASSERT_NE(two, std::string::npos) << with.out;
    ASSERT_NE(three, std::string::npos) << with.out;
    EXPECT_LT(one, two);
    EXPECT_LT(two, three);
    EXPECT_LT(three, png);
    const CommandResult without = glpreview(common + " -o " + (dir.path() / "without").string(), dir);
    ASSERT_EQ(without.exit_code, 0) << without.err;
    EXPECT_FALSE(Contains(without.out, "sheet-progress"));
    EXPECT_FALSE(Contains(without.err, "rows"));
    EXPECT_EQ(read_file(dir.path() / "with" / "sheet.png"), read_file(dir.path() / "without" / "sheet.png"));
    EXPECT_EQ(glpreview(sheet_scene() + " --sheet-progress -o " + (dir.path() / "x").string(), dir).exit_code, 2);
}

// Issue 32 (metalfit report's renders): --sheet-rows writes each row as its own image, the row's Fresnel made for it
// alone; each image is the sheet of that one material made by a run of its own (byte for byte: the same renders,
// error views and labels), sheet.json is the whole sheet's record with the row numbers of the sheet, and no sheet
// image is written; stdout names the folder, not every cell (nothing of a row is kept).
TEST(PreviewSheet, SheetRowsWritesEachRowAsTheSheetOfItsMaterialAlone) {
    TempDir dir;
    const std::string models = " --sheet-models schlick,conductor-rgb" + kSize;
    const CommandResult rows = glpreview(sheet_scene() + " --sheet Au,Cu,Ti --sheet-rows --sheet-progress" + models +
                                             " -o " + (dir.path() / "rows").string(),
                                         dir);
    ASSERT_EQ(rows.exit_code, 0) << rows.err;
    EXPECT_TRUE(Contains(rows.out, "sheet-progress 3 3\n")) << rows.out;
    EXPECT_FALSE(fs::exists(dir.path() / "rows" / "sheet.png"));
    EXPECT_FALSE(fs::exists(dir.path() / "rows" / "sheet.exr"));
    const Json record = Json::parse(read_file(dir.path() / "rows" / "sheet.json"));
    ASSERT_EQ(record.size(), 3u * 2u);
    const std::vector<std::string> materials{"Au", "Cu", "Ti"};
    std::set<std::string> images;
    for (std::size_t row = 0; row < materials.size(); ++row) {
        const fs::path alone = dir.path() / ("alone-" + materials[row]);
        const CommandResult one =
            glpreview(sheet_scene() + " --sheet " + materials[row] + models + " -o " + alone.string(), dir);
        ASSERT_EQ(one.exit_code, 0) << one.err;
        const std::string image = read_file(dir.path() / "rows" / "rows" / (std::to_string(row) + ".png"));
        EXPECT_EQ(image, read_file(alone / "sheet.png")) << materials[row];
        images.insert(image);
        const Json one_record = Json::parse(read_file(alone / "sheet.json"));
        for (std::size_t m = 0; m < 2; ++m) {
            Json entry = record[2 * row + m];
            EXPECT_EQ(entry["row"], row);
            entry["row"] = 0;
            // The row's error-view scale, what its labels print: a decade range ending at the floor or above.
            const double smallest = entry["error_view"]["smallest"].get<double>(),
                         largest = entry["error_view"]["largest"].get<double>();
            EXPECT_GE(smallest, 1e-5);
            EXPECT_GT(largest, smallest);
            EXPECT_EQ(entry["error_view"], record[2 * row]["error_view"]) << "one scale a row";
            entry.erase("error_view");
            EXPECT_EQ(entry, one_record[m]) << materials[row];
        }
    }
    EXPECT_EQ(images.size(), 3u) << "three materials, three different images";
    // sheet.json, written a row at a time, is the whole sheet's record for the same rows with each row's scale.
    const CommandResult whole =
        glpreview(sheet_scene() + " --sheet Au,Cu,Ti" + models + " -o " + (dir.path() / "whole").string(), dir);
    ASSERT_EQ(whole.exit_code, 0) << whole.err;
    Json without_scales = record;
    for (Json& entry : without_scales) entry.erase("error_view");
    EXPECT_EQ(without_scales, Json::parse(read_file(dir.path() / "whole" / "sheet.json")));
    EXPECT_EQ(glpreview(sheet_scene() + " --sheet-rows -o " + (dir.path() / "x").string(), dir).exit_code, 2);
}

}  // namespace test_preview_sheet
}  // namespace metalfit::test
