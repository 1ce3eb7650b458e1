// Four- and five-axis machining-centre kinematics (the course notes' §5,
// 004:1436-2018; pupitre(1), MACHINE PROFILES): the tool frame in the part
// frame from the axis positions (forward) and the axis positions for a wanted
// tool frame (inverse), with homogeneous transforms (Eigen::Isometry3d). Angles
// in degrees at the interface.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <Eigen/Geometry>
#include <optional>

namespace pupitre::kin {

struct Pose4 {  // X Y Z B of the mill4 (B rotary table about Y)
    double x = 0, y = 0, z = 0, b = 0;
};
struct Pose5 {  // X Y Z B C of the mill5 (C table about Z, B head about Y)
    double x = 0, y = 0, z = 0, b = 0, c = 0;
};

// Mill4: L = position of the part origin relative to the table axis (L_X, L_Z).
Eigen::Isometry3d forward4(const Pose4& p, double lx, double lz);
// nullopt when the target is not reachable (not a rotation about Y).
std::optional<Pose4> inverse4(const Eigen::Isometry3d& h, double lx, double lz);

// Mill5: L_X, L_Y, L_Z are the offsets with all axes at zero (004:1744-1746).
Eigen::Isometry3d forward5(const Pose5& p, double lx, double ly, double lz);
std::optional<Pose5> inverse5(const Eigen::Isometry3d& h, double lx, double ly, double lz);

}  // namespace pupitre::kin
