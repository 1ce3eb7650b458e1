// 4- and 5-axis kinematics: the test vectors of 004:1588-1801, computed from
// the course notes' formulas (004:1654-1801), and forward/inverse round trips.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>

#include "core/geometry/kinematics.hpp"
#include "helpers.hpp"

using namespace pupitre;

TEST(Kinematics, Mill4TestVector) {
    Eigen::Isometry3d h = kin::forward4({10, 20, 30, 30}, 100, 50);
    Eigen::Matrix<double, 3, 4> want;
    want << 0.866025, 0, 0.5, 35.262794, 0, 1, 0, 20, -0.5, 0, 0.866025, -35.717968;
    EXPECT_TRUE(h.matrix().topRows<3>().isApprox(want, 1e-6)) << h.matrix();
    auto p = kin::inverse4(h, 100, 50);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x, 10, 1e-9);
    EXPECT_NEAR(p->y, 20, 1e-9);
    EXPECT_NEAR(p->z, 30, 1e-9);
    EXPECT_NEAR(p->b, 30, 1e-9);
}

TEST(Kinematics, Mill5TestVector) {
    Eigen::Isometry3d h = kin::forward5({10, 20, 30, 30, 45}, 100, -40, 250);
    Eigen::Matrix<double, 3, 4> want;
    want << 0.612372, -0.707107, 0.353553, -96.464466, 0.612372, 0.707107, 0.353553, 15.251263,
        -0.5, 0, 0.866025, 63.493649;
    EXPECT_TRUE(h.matrix().topRows<3>().isApprox(want, 1e-6)) << h.matrix();
    auto p = kin::inverse5(h, 100, -40, 250);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x, 10, 1e-9);
    EXPECT_NEAR(p->y, 20, 1e-9);
    EXPECT_NEAR(p->z, 30, 1e-9);
    EXPECT_NEAR(p->b, 30, 1e-9);
    EXPECT_NEAR(p->c, 45, 1e-9);
}

TEST(Kinematics, RoundTripsAndUnreachable) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-200, 200), a(-179, 179);
    for (int i = 0; i < 500; ++i) {
        kin::Pose4 p4{u(rng), u(rng), u(rng), a(rng)};
        auto q4 = kin::inverse4(kin::forward4(p4, 80, -30), 80, -30);
        ASSERT_TRUE(q4);
        EXPECT_NEAR(q4->x, p4.x, 1e-7);
        EXPECT_NEAR(q4->b, p4.b, 1e-7);
        kin::Pose5 p5{u(rng), u(rng), u(rng), a(rng) / 2, a(rng)};
        auto q5 = kin::inverse5(kin::forward5(p5, 100, -40, 250), 100, -40, 250);
        ASSERT_TRUE(q5);
        EXPECT_NEAR(q5->y, p5.y, 1e-7);
        EXPECT_NEAR(q5->c, p5.c, 1e-7);
    }
    // A rotation about X cannot be reached by the B table.
    Eigen::Isometry3d h = Eigen::Isometry3d::Identity();
    h.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
    EXPECT_FALSE(kin::inverse4(h, 0, 0));
}

TEST(Kinematics, Program170ComputesItsOwnFrame) {
    // 004:1955-2016: the inverse model in L variables gives the G59 of the inclined plane.
    MachineProfile m;
    ASSERT_TRUE(builtin_machine("mill4", m));
    ProgramMemory mem;
    const std::string path =
        std::string(PUPITRE_SOURCE_DIR) + "/tests/golden/programs/004_p170.iso";
    const std::optional<Diag> d = mem.load_file(path);
    ASSERT_FALSE(d) << d->detail;
    test::Capture cap;
    Interpreter in(m, mem, cap);
    in.start(mem.first());
    in.run_to_end();
    ASSERT_FALSE(in.has_errors()) << format_diag(in.diags().front());
    EXPECT_NEAR(in.lvars().v[16], 186.8424, 5e-5);
    EXPECT_NEAR(in.lvars().v[17], 209.0373, 5e-5);
    // The program's formulas are the inverse model of the four-axis centre
    // (004:1588-1718): the frame R2 (Rp
    // turned by B30 about Y, origin at (70, 75, 34.225)) with the table axis at
    // L_X = L14, L_Z = L15 gives X = L16 and Z = L17.
    const auto& L = in.lvars().v;
    Eigen::Isometry3d h = Eigen::Isometry3d::Identity();
    h.linear() = Eigen::AngleAxisd(L[10] * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
    h.translation() = Eigen::Vector3d(L[11], L[12], L[13]);
    auto p = kin::inverse4(h, L[14], L[15]);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x, L[16], 1e-9);
    EXPECT_NEAR(p->z, L[17], 1e-9);
    EXPECT_NEAR(p->b, 30, 1e-9);
}
