// The plot's scene (issue 12.11): the frame fits the cutting moves and leaves
// out the rapids from home, the scale is round, the legend lists the layers
// that leave ink, and both back-ends draw it: the SVG with its promised layers
// and exact coordinates, Cairo as a PNG and a PDF.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/output/cairo_plot.hpp"
#include "core/output/scene.hpp"
#include "core/output/svg.hpp"
#include "tests/plot/plot_run.hpp"

using namespace pupitre;

namespace {

test::PlotRun run_text(const std::string& machine, const std::string& text,
                       const std::vector<std::pair<std::string, double>>& sets = {}) {
    return test::run_text("scene", machine, text, sets);
}

Scene scene_of(const test::PlotRun& r, PathPlane plane) {
    SceneOptions o;
    o.plane = plane;
    return build_scene(*r.path, o);
}

bool legend_has(const Scene& s, const std::string& words) {
    for (const Mark& m : s.marks)
        if (m.group == Mark::legend && m.kind == Mark::text && m.words == words) return true;
    return false;
}

std::string notes(const Scene& s) {
    std::string t;
    for (const Mark& m : s.marks)
        if (m.kind == Mark::text) t += m.words + "\n";
    return t;
}

// 1, 2 or 5 times a power of ten.
bool round_number(double v) {
    double p = std::pow(10.0, std::floor(std::log10(v) + 1e-9));
    double m = v / p;
    return std::fabs(m - 1) < 1e-9 || std::fabs(m - 2) < 1e-9 || std::fabs(m - 5) < 1e-9;
}

// A 40 mm square cut near the origin, reached by a rapid from X300 Y200.
const char* kSquare =
    "%41 (SQUARE)\nN10 G0 X300 Y200 Z50\nN20 X0 Y0 Z2\nN30 G1 Z-1 F300\nN40 X40\nN50 Y40\n"
    "N60 X0\nN70 Y0\nN80 G0 Z50\nN90 X300 Y200\nM2\n";

std::string read_all(const std::string& path) {
    std::string s;
    if (FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[4096];
        size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
        std::fclose(f);
    }
    return s;
}

}  // namespace

TEST(Scene, FrameFitsTheCuttingMovesNotTheRapidsFromHome) {
    auto r = run_text("mill", kSquare);
    Scene s = scene_of(r, PathPlane::xy);
    EXPECT_EQ(s.fit.what, PathFit::cuts);
    EXPECT_DOUBLE_EQ(s.fit.x0, 0);
    EXPECT_DOUBLE_EQ(s.fit.x1, 40);
    EXPECT_DOUBLE_EQ(s.fit.y1, 40);
    EXPECT_LT(s.wx1, 60);          // X300 is far outside: clipped
    EXPECT_LT(s.wx0, 0);           // a margin on each side
    EXPECT_EQ(s.fit.outside, 3u);  // out to X300 Y200, back, and out again
    EXPECT_NE(notes(s).find("frame fitted to the cutting moves of %41 (3 rapids reach beyond), "
                            "clipped at the frame"),
              std::string::npos)
        << notes(s);
    // The frame on the page is the window at the scale.
    EXPECT_NEAR(s.fw, (s.wx1 - s.wx0) * s.k, 1e-9);
    EXPECT_NEAR(s.px(s.wx1), s.fx + s.fw, 1e-9);
    EXPECT_NEAR(s.py(s.wy0), s.fy + s.fh, 1e-9);
}

TEST(Scene, OnlyRapidsFitTheWholePath) {
    auto r = run_text("mill", "%42\nN10 G0 X10 Y0\nN20 X10 Y20\nM2\n");
    Scene s = scene_of(r, PathPlane::xy);
    EXPECT_EQ(s.fit.what, PathFit::moves);
    EXPECT_EQ(fit_words(*r.path, s.fit), "the whole path of %42 (no cutting move)");
    EXPECT_DOUBLE_EQ(s.fit.y1, 20);
}

TEST(Scene, ScaleAndScaleBarAreRoundNumbers) {
    for (double side : {0.3, 4.0, 40.0, 170.0, 900.0, 12000.0}) {
        char text[200];
        std::snprintf(text, sizeof text, "%%43\nN10 G0 X0 Y0\nN20 G1 X%g F100\nN30 Y%g\nM2\n", side,
                      side / 2);
        auto r = run_text("mill", text);
        Scene s = scene_of(r, PathPlane::xy);
        EXPECT_TRUE(round_number(s.k)) << side << ": k " << s.k;
        EXPECT_TRUE(round_number(s.bar_length)) << side << ": bar " << s.bar_length;
        double on_paper = s.bar_length * s.k;
        EXPECT_GE(on_paper, 12) << side;
        EXPECT_LE(on_paper, 30) << side;
        // The drawing fits about an A4 page and is not lost on it.
        EXPECT_LE(s.fw, 257) << side;
        EXPECT_LE(s.fh, 215) << side;
        EXPECT_GE(std::max(s.fw, s.fh), 60) << side;
    }
}

TEST(Scene, LegendListsTheLayersThatLeaveInk) {
    auto plain = run_text("mill", kSquare);
    Scene s = scene_of(plain, PathPlane::xy);
    EXPECT_TRUE(legend_has(s, "rapid G0"));
    EXPECT_TRUE(legend_has(s, "feed G1 G2 G3"));
    EXPECT_FALSE(legend_has(s, "compensated path G41 G42"));
    EXPECT_FALSE(legend_has(s, "programmed profile"));
    EXPECT_FALSE(legend_has(s, "spindle axis"));
    // Seen from the front (XZ) the square is a line, its plunge a stroke: still ink.
    Scene front = scene_of(plain, PathPlane::xz);
    EXPECT_TRUE(legend_has(front, "feed G1 G2 G3"));

    auto comp = run_text("mill",
                         "%44\nN10 T1 D1 M6\nN20 G0 X-20 Y-20 Z2\nN30 G1 G41 X0 Y0 F200\nN40 X40\n"
                         "N50 G3 X40 Y20 R10\nN60 G1 X0\nN70 G40 X-20 Y-20\nM2\n",
                         {{"D1.R", 5}});
    Scene c = scene_of(comp, PathPlane::xy);
    EXPECT_TRUE(legend_has(c, "compensated path G41 G42"));
    EXPECT_TRUE(legend_has(c, "programmed profile"));
    // The programmed profile is the program's, not the tool's: X0 Y0 to X40, then the arc.
    const auto& pe = comp.path->profile_elems();
    ASSERT_GE(pe.size(), 3u);
    EXPECT_DOUBLE_EQ(pe[1].from[0], 0);
    EXPECT_DOUBLE_EQ(pe[1].to[0], 40);
    EXPECT_TRUE(pe[2].arc);
    EXPECT_NEAR(pe[2].sweep, 180, 1e-9);
    // The profile is in the frame: the arc's far side at X50.
    EXPECT_GE(c.fit.x1, 50 - 1e-9);
}

// The PDF's table of each tool's time (issue 35): a header and a row per
// tool, under the notes, the page taller for it; none without tools.
TEST(Scene, TheToolTableListsEachTool) {
    auto r = run_text("mill", kSquare);
    SceneOptions o;
    o.plane = PathPlane::xy;
    const Scene plain = build_scene(*r.path, o);
    o.tools = {plan::ToolRow{.tool = 11,
                             .cut_seconds = 141.78,
                             .rapid_seconds = 6.6,
                             .cut_length = 424.44,
                             .passes = 3},
               plan::ToolRow{.tool = 12, .cut_seconds = 138.4}};
    o.life.all = 15 * 60;
    const Scene table = build_scene(*r.path, o);
    auto words = [](const Scene& s) {
        std::string t;
        for (const Mark& m : s.marks)
            if (m.kind == Mark::text) t += m.words + "|";
        return t;
    };
    EXPECT_EQ(words(plain).find("parts per edge"), std::string::npos);
    const std::string t = words(table);
    for (const char* w : {"tool|", "cutting s|", "parts per edge|", "T11|", "141.8|", "3|",
                          "424.440|", "6.6|", "6|", "T12|", "138.4|"})
        EXPECT_NE(t.find(w), std::string::npos) << w;
    EXPECT_GT(table.page_h, plain.page_h);
}

TEST(Scene, LatheMirrorImageIsFittedNearTheAxisOnly) {
    // A bar turned from the axis: the half-profile and its mirror image.
    auto bar = run_text("lathe",
                        "%45\nN10 G0 X200 Z200\nN20 X0 Z2\nN30 G1 Z0 F0.2\nN40 X40\nN50 Z-30\nN60 "
                        "G0 X200 Z200\nM2\n");
    Scene b = scene_of(bar, PathPlane::zx);
    EXPECT_TRUE(b.mirror);
    EXPECT_FALSE(b.fit.mirror_out);
    EXPECT_DOUBLE_EQ(b.fit.y0, -20);  // X40 is a radius of 20, mirrored
    EXPECT_TRUE(legend_has(b, "mirror image below the axis"));
    EXPECT_TRUE(legend_has(b, "spindle axis"));
    // A rim: cuts at a radius of 150 to 160, far from the axis.
    auto rim = run_text("lathe",
                        "%46\nN10 G0 X400 Z50\nN20 X320 Z2\nN30 G1 Z-20 F0.2\nN40 X300\nN50 G0 "
                        "X400 Z50\nM2\n");
    Scene r = scene_of(rim, PathPlane::zx);
    EXPECT_TRUE(r.fit.mirror_out);
    EXPECT_DOUBLE_EQ(r.fit.y0, 150);
    EXPECT_FALSE(legend_has(r, "mirror image below the axis"));
    EXPECT_FALSE(legend_has(r, "spindle axis"));
    EXPECT_NE(fit_words(*rim.path, r.fit).find("the mirror image left out, far from the axis"),
              std::string::npos);
}

TEST(Scene, SvgKeepsItsLayersAndAddsTheMarks) {
    auto r = run_text("mill", kSquare);
    std::string svg = svg_document(scene_of(r, PathPlane::xy));
    for (const char* id : {"rapid", "feed", "comp", "travel", "gouge", "title", "axes", "scale-bar",
                           "legend", "notes", "border"})
        EXPECT_NE(svg.find(std::string("<g id=\"") + id + "\""), std::string::npos) << id;
    // Every move is kept with its exact coordinates; the frame clips what reaches beyond.
    EXPECT_NE(svg.find("M0.0000 0.0000 L300.0000 -200.0000 L0.0000 0.0000"), std::string::npos)
        << svg;
    EXPECT_NE(svg.find("<clipPath id=\"window\">"), std::string::npos);
    EXPECT_NE(svg.find("clip-path=\"url(#window)\""), std::string::npos);
    EXPECT_NE(svg.find(">feed G1 G2 G3</text>"), std::string::npos);
}

TEST(Scene, CairoWritesAPngAndAPdf) {
    auto r = run_text("lathe",
                      "%47 (BAR)\nN10 G0 X200 Z200\nN20 X0 Z2\nN30 G1 Z0 F0.2\nN40 X40\nN50 G3 "
                      "X50 Z-5 R5\nN60 G1 Z-30\nN70 G0 X200 Z200\nM2\n");
    Scene s = scene_of(r, PathPlane::zx);
    std::string base = ::testing::TempDir() + "/scene_cairo_" + std::to_string(::getpid());
    FILE* f = std::fopen((base + ".png").c_str(), "wb");
    ASSERT_TRUE(f);
    EXPECT_TRUE(write_png(s, 800, f));
    std::fclose(f);
    std::string png = read_all(base + ".png");
    ASSERT_GT(png.size(), 24u);
    EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
    // IHDR: the width asked, the height of the page's proportions.
    auto be32 = [&](size_t at) {
        return uint32_t(uint8_t(png[at])) << 24 | uint32_t(uint8_t(png[at + 1])) << 16 |
               uint32_t(uint8_t(png[at + 2])) << 8 | uint32_t(uint8_t(png[at + 3]));
    };
    EXPECT_EQ(be32(16), 800u);
    EXPECT_NEAR(double(be32(20)), std::ceil(s.page_h * 800 / s.page_w), 1);
    f = std::fopen((base + ".pdf").c_str(), "wb");
    ASSERT_TRUE(f);
    EXPECT_TRUE(write_pdf(s, f));
    std::fclose(f);
    std::string pdf = read_all(base + ".pdf");
    EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
    EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
    std::remove((base + ".png").c_str());
    std::remove((base + ".pdf").c_str());
}

TEST(Scene, TextEstimateIsNotNarrowerThanTheFont) {
    // Cairo's advances in DejaVu Sans (ems, no hinting), measured once: the
    // estimate may be a little wide, never narrow, and not much wide either.
    struct Case {
        const char* text;
        bool bold;
        double ems;
    };
    for (const Case& c :
         {Case{"%555  EXEMPLE EN TOURNAGE", true, 17.417},
          Case{"cycle time 0:04:47 (287.800 s)", false, 15.407},
          Case{"ABCDEFGHIJKLMNOPQRSTUVWXYZ", false, 17.489},
          Case{"compensated path G41 G42", true, 15.620},
          Case{"extents  X\xc3\xb8 0.000/300.000  Z -17.000/200.000", false, 23.317}}) {
        EXPECT_GE(text_ems(c.text, c.bold), c.ems) << c.text;
        EXPECT_LE(text_ems(c.text, c.bold), 1.15 * c.ems) << c.text;
    }
    EXPECT_DOUBLE_EQ(text_ems("\xc3\xb8"), text_ems("\xe2\x80\xa6"));  // one character each
}
