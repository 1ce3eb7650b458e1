// The PART view's pictures (issue 36): golden images of the lathe's section,
// the mill's height map from above and its 3-D view, compared pixel by
// pixel with a tolerance (PUPITRE_BLESS=1 rewrites them, when a change is
// intended); the deviation colours on a part cut 0.05 mm over size; the
// camera's steps; the picture made from a copy of the workshop.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "../unit/workshop_run.hpp"
#include "core/render/part_view.hpp"
#include "core/render/surfaces.hpp"

namespace pupitre::render {
namespace {

using test::Sets;

const char* kTurn = R"(%10
N10 T1 D1 M6
N20 S1000 M3
N30 G95 F0.2
N40 G0 X56 Z2
N50 G1 Z-40
N60 X62
N70 G0 Z2
N80 X50
N90 G1 Z-20
N100 X58
N110 G0 X70 Z5
N120 M2
)";

// The shipped lathe's truth: PREF X -20 (a radius) Z 35, T1's gauge X
// 52.347 Z 41.215; `over` mm more on PREF X cuts each diameter 2 x over.
Sets lathe_values(double over = 0) {
    return {{"PREF.X", -20 + over}, {"PREF.Z", 35}, {"D1.X", 52.347}, {"D1.Z", 41.215}};
}

Drawing lathe_drawing() {
    return {"drawing T",
            {{"dia Z-10", 50, -0.02, 0.02},
             {"dia Z-30", 56, -0.02, 0.02},
             {"length", 95, -0.05, 0.05}}};
}

const char* kSlot = R"(%30
N10 T2 D2 M6
N20 S2000 M3
N30 G0 X-70 Y0 Z5
N40 G1 Z-3 F300
N50 X70 F400
N60 G0 Z5
N70 X20 Y20
N80 G1 Z-5 F200
N90 X40 F300
N100 Y26
N110 X20
N120 Y20
N130 G0 Z20
N135 X-10 Y-10
N140 M2
)";

Sets mill_values(double pref_z = -290) {
    return {
        {"PREF.X", 108.35}, {"PREF.Y", -91.72}, {"PREF.Z", pref_z}, {"D2.L", 117.645}, {"D2.R", 4}};
}

Drawing mill_drawing() {
    return {"drawing S",
            {{"depth X60 Y40", 3, -0.02, 0.02},
             {"width Y X10 Y40 Z-1", 8, -0.02, 0.02},
             {"depth X90 Y63", 5, -0.02, 0.02}}};
}

struct Cut {
    test::ShopRun run;
    std::shared_ptr<const PartScene> scene;
    Cut(const char* kind, const char* program, const Sets& sets, const Drawing* d)
        : run(kind, program, sets, "") {
        EXPECT_EQ(run.crash(), 0);
        scene = snapshot(*run.shop, run.in->machine_pos(), d);
    }
};

// A golden picture (tests/render/golden/NAME.png): each pixel within 24 of
// it on every channel, all but 0.5 % of them.
void golden(const Image& img, const std::string& name) {
    const std::string path =
        std::string(PUPITRE_SOURCE_DIR) + "/tests/render/golden/" + name + ".png";
    if (const char* b = std::getenv("PUPITRE_BLESS"); b && *b) {
        cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, img.w(), img.h());
        auto* data = cairo_image_surface_get_data(s);
        const int stride = cairo_image_surface_get_stride(s);
        for (int y = 0; y < img.h(); ++y)
            for (int x = 0; x < img.w(); ++x) {
                const Colour c = img.at(x, y);
                reinterpret_cast<uint32_t*>(data + y * stride)[x] =
                    red(c) << 16 | green(c) << 8 | blue(c);
            }
        cairo_surface_mark_dirty(s);
        ASSERT_EQ(cairo_surface_write_to_png(s, path.c_str()), CAIRO_STATUS_SUCCESS);
        cairo_surface_destroy(s);
        return;
    }
    cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
    ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS)
        << path << " (PUPITRE_BLESS=1 makes it)";
    ASSERT_EQ(cairo_image_surface_get_width(s), img.w());
    ASSERT_EQ(cairo_image_surface_get_height(s), img.h());
    const auto* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    long off = 0;
    for (int y = 0; y < img.h(); ++y)
        for (int x = 0; x < img.w(); ++x) {
            const uint32_t g = reinterpret_cast<const uint32_t*>(data + y * stride)[x];
            const Colour c = img.at(x, y);
            const int d = std::max({std::abs(int(red(c)) - int((g >> 16) & 0xff)),
                                    std::abs(int(green(c)) - int((g >> 8) & 0xff)),
                                    std::abs(int(blue(c)) - int(g & 0xff))});
            if (d > 24) ++off;
        }
    cairo_surface_destroy(s);
    EXPECT_LE(off, long(img.w()) * img.h() / 200) << name << ": " << off << " pixels differ";
}

TEST(PartPicture, LatheSectionGolden) {
    const Drawing d = lathe_drawing();
    Cut c("lathe", kTurn, lathe_values(), &d);
    const auto sf = prepare(*c.scene, Paint::deviation);
    Look look;
    const Picture p = render(*c.scene, *sf, look, 480, 320);
    golden(p.image, "lathe_section");
    EXPECT_TRUE(p.has_stickout);
    EXPECT_NEAR(p.stickout, 95, 1e-6);
}

TEST(PartPicture, MillTopGolden) {
    const Drawing d = mill_drawing();
    Cut c("mill", kSlot, mill_values(), &d);
    const auto sf = prepare(*c.scene, Paint::deviation);
    Look look;
    look.mode = PartMode::top;
    golden(render(*c.scene, *sf, look, 480, 320).image, "mill_top");
}

TEST(PartPicture, Mill3dGolden) {
    Cut c("mill", kSlot, mill_values(), nullptr);
    const auto sf = prepare(*c.scene, Paint::depth);
    Look look;
    look.mode = PartMode::iso;
    golden(render(*c.scene, *sf, look, 480, 320).image, "mill_3d");
}

// The colour an edge of the outline at R `r` about Z `z` is painted.
Colour edge_at(const Surfaces& sf, double z, double r) {
    for (size_t p = 0; p < sf.outline.size(); ++p)
        for (size_t k = 0; k < sf.outline[p].size(); ++k) {
            const auto a = sf.outline[p][k], b = sf.outline[p][(k + 1) % sf.outline[p].size()];
            if (std::abs(a[1] - r) < 0.01 && std::abs(b[1] - r) < 0.01 &&
                std::min(a[0], b[0]) <= z && z <= std::max(a[0], b[0]))
                return sf.edge[p][k];
        }
    return 0;
}

bool reddish(Colour c) {
    return red(c) > 180 && green(c) < 200 && blue(c) < 80;
}

// PREF X 0.025 mm over (a radius): both diameters 0.05 over, painted
// "over"; the face, read by length, within its tolerance.
TEST(PartPicture, LatheCut005OverIsPaintedOver) {
    const Drawing d = lathe_drawing();
    Cut c("lathe", kTurn, lathe_values(0.025), &d);
    ASSERT_EQ(c.scene->dims.size(), 3u);
    EXPECT_EQ(c.scene->dims[0].verdict(), Verdict::over);
    EXPECT_NEAR(c.scene->dims[0].deviation(), 0.05, 1e-6);
    EXPECT_EQ(c.scene->dims[1].verdict(), Verdict::over);
    EXPECT_EQ(c.scene->dims[2].verdict(), Verdict::inside);
    const auto sf = prepare(*c.scene, Paint::deviation);
    EXPECT_EQ(sf->legend.paint, Paint::deviation);
    const Colour over50 = edge_at(*sf, 35 - 10, 25.025), over56 = edge_at(*sf, 35 - 30, 28.025);
    EXPECT_TRUE(reddish(over50)) << std::hex << over50;
    EXPECT_TRUE(reddish(over56)) << std::hex << over56;
    EXPECT_EQ(over50, deviation_colour(50, -20, 20, sf->legend.span_um));
    // The shoulder between them is on no dimension.
    bool face_inside = false;
    for (size_t p = 0; p < sf->outline.size(); ++p)
        for (size_t k = 0; k < sf->outline[p].size(); ++k) {
            const auto a = sf->outline[p][k], b = sf->outline[p][(k + 1) % sf->outline[p].size()];
            if (std::abs(a[0] - 35) < 1e-3 && std::abs(b[0] - 35) < 1e-3)
                face_inside = face_inside || sf->edge[p][k] == kInside;
        }
    EXPECT_TRUE(face_inside);
    // Right values: in tolerance, green.
    Cut right("lathe", kTurn, lathe_values(), &d);
    const auto sr = prepare(*right.scene, Paint::deviation);
    EXPECT_EQ(edge_at(*sr, 35 - 10, 25), kInside);
    EXPECT_EQ(edge_at(*sr, 35 - 30, 28), kInside);
}

// The picture shows it too: below the axis, the outside view's columns
// over the Ø50 are red, those over Ø56 as well; with right values green.
TEST(PartPicture, LatheSilhouetteShowsTheColours) {
    const Drawing d = lathe_drawing();
    for (double over : {0.025, 0.0}) {
        Cut c("lathe", kTurn, lathe_values(over), &d);
        const auto sf = prepare(*c.scene, Paint::deviation);
        const Picture p = render(*c.scene, *sf, Look{}, 480, 320);
        // The anchor of dia Z-10 is on the Ø50's surface; its mirror below
        // the axis, a few pixels in, is its outside view.
        ASSERT_FALSE(std::isnan(p.anchor[0][0]));
        const int x = int(p.anchor[0][0]);
        const int axis = 160;  // unpanned, the axis is the middle row
        const Colour below = p.image.at(x, axis + 8);
        if (over > 0)
            EXPECT_GT(int(red(below)), int(green(below)) + 40) << std::hex << below;
        else
            EXPECT_GT(int(green(below)), int(red(below)) + 40) << std::hex << below;
    }
}

// Depth 0.05 over on the mill (PREF Z 0.05 low): the slot's floor and the
// pocket's, read by the depth gauge, over; the slot's walls in tolerance.
TEST(PartPicture, MillCut005DeepIsPaintedOver) {
    const Drawing d = mill_drawing();
    Cut c("mill", kSlot, mill_values(-290.05), &d);
    ASSERT_EQ(c.scene->dims.size(), 3u);
    EXPECT_EQ(c.scene->dims[0].verdict(), Verdict::over);
    EXPECT_EQ(c.scene->dims[1].verdict(), Verdict::inside);
    EXPECT_EQ(c.scene->dims[2].verdict(), Verdict::over);
    const auto sf = prepare(*c.scene, Paint::deviation);
    const Level& l = sf->block.front();
    const double cell = l.cell;
    // The slot's floor at X60 Y40 from the corner, the pocket's at X90 Y63.
    EXPECT_TRUE(reddish(l.colour(int(60 / cell), int(40 / cell))));
    EXPECT_TRUE(reddish(l.colour(int(90 / cell), int(63 / cell))));
    // The block's top, far from both: on no dimension.
    EXPECT_EQ(l.colour(int(10 / cell), int(10 / cell)), kUnmarked);
    // The slot's wall at Y44 (its +Y side), read by the caliper: green.
    EXPECT_EQ(l.colour(int(30 / cell), int(44.05 / cell)), kInside);
}

TEST(PartPicture, DepthWhenThereIsNoDrawing) {
    Cut c("mill", kSlot, mill_values(), nullptr);
    const auto sf = prepare(*c.scene, Paint::deviation);
    EXPECT_EQ(sf->paint, Paint::depth);
    const Level& l = sf->block.front();
    EXPECT_EQ(l.colour(int(10 / l.cell), int(10 / l.cell)), kUncut);
    EXPECT_EQ(l.colour(int(60 / l.cell), int(40 / l.cell)), depth_colour(3.0 / sf->legend.depth));
}

TEST(PartPicture, CameraSteps) {
    Camera c;
    EXPECT_DOUBLE_EQ(turned(c, 330).yaw, 30);
    EXPECT_DOUBLE_EQ(turned(c, -75).yaw, 345);
    EXPECT_DOUBLE_EQ(tilted(c, 100).pitch, kMaxPitch);
    EXPECT_DOUBLE_EQ(tilted(c, -100).pitch, kMinPitch);
    Camera p = panned(c, 0.1, 0);
    Camera z = zoomed(p, 2);
    EXPECT_DOUBLE_EQ(z.zoom, 2);
    EXPECT_DOUBLE_EQ(z.pan_x, 0.2);  // the same point at the centre
    EXPECT_DOUBLE_EQ(zoomed(c, 1e6).zoom, kMaxZoom);
    EXPECT_EQ(next_mode(PartMode::top, true), PartMode::iso);
    EXPECT_EQ(next_mode(PartMode::iso, true), PartMode::top);
    EXPECT_EQ(next_mode(PartMode::section, false), PartMode::section);
    EXPECT_FALSE(mode_fits(PartMode::top, false));
}

// The picture is the scene's: the same scene, surfaces and look give the
// same pixels; the scene is a copy, so cutting on does not change it.
TEST(PartPicture, TheSceneIsACopy) {
    Cut c("mill", kSlot, mill_values(), nullptr);
    const auto sf = prepare(*c.scene, Paint::depth);
    Look look;
    look.mode = PartMode::iso;
    const Image a = render(*c.scene, *sf, look, 200, 120).image;
    c.run.shop->new_part();
    const Image b = render(*c.scene, *sf, look, 200, 120).image;
    EXPECT_EQ(a.pixels(), b.pixels());
}

}  // namespace
}  // namespace pupitre::render
