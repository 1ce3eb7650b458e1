// Kinematic models of the mill4 and mill5 (004:1588-1801; pupitre(1), MACHINE PROFILES).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/geometry/kinematics.hpp"

#include <cmath>

#include "core/geometry/geometry.hpp"

namespace pupitre::kin {

namespace {
using ::pupitre::geometry::kDeg;
Eigen::Isometry3d trans(double a, double b, double c) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(a, b, c);
    return t;
}
Eigen::Isometry3d rot(double deg, const Eigen::Vector3d& axis) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(deg * kDeg, axis).toRotationMatrix();
    return t;
}
bool orthonormal(const Eigen::Matrix3d& m) {
    return (m.transpose() * m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9 &&
           std::fabs(m.determinant() - 1) < 1e-9;
}
}  // namespace

// H_RpRo = Trans(-L_X,0,-L_Z) . Rot_Y(B) . Trans(X,0,0) . Trans(0,0,Z) . Trans(0,Y,0) .
// Trans(L_X,0,L_Z)
Eigen::Isometry3d forward4(const Pose4& p, double lx, double lz) {
    return trans(-lx, 0, -lz) * rot(p.b, Eigen::Vector3d::UnitY()) * trans(p.x, 0, 0) *
           trans(0, 0, p.z) * trans(0, p.y, 0) * trans(lx, 0, lz);
}

std::optional<Pose4> inverse4(const Eigen::Isometry3d& h, double lx, double lz) {
    const Eigen::Matrix3d& m = h.linear();
    // Reachable: a rotation about Y only (004:1663).
    if (!orthonormal(m) || std::fabs(m(1, 1) - 1) > 1e-9) return std::nullopt;
    double beta = std::atan2(m(0, 2), m(0, 0));
    double a = h.translation().x(), b = h.translation().y(), c = h.translation().z();
    double cb = std::cos(beta), sb = std::sin(beta);
    Pose4 p;
    p.b = beta / kDeg;
    p.y = b;
    p.x = -lx + (lx + a) * cb - (lz + c) * sb;
    p.z = -lz + (lx + a) * sb + (lz + c) * cb;
    return p;
}

// H_RpRo = Trans(-L_X,-L_Y,0) . Rot_Z(C) . Trans(0,Y,0) . Trans(X,0,0) . Trans(L_X,L_Y,Z+L_Z) .
// Rot_Y(B)
//          . Trans(0,0,-L_Z)
Eigen::Isometry3d forward5(const Pose5& p, double lx, double ly, double lz) {
    return trans(-lx, -ly, 0) * rot(p.c, Eigen::Vector3d::UnitZ()) * trans(0, p.y, 0) *
           trans(p.x, 0, 0) * trans(lx, ly, p.z + lz) * rot(p.b, Eigen::Vector3d::UnitY()) *
           trans(0, 0, -lz);
}

std::optional<Pose5> inverse5(const Eigen::Isometry3d& h, double lx, double ly, double lz) {
    const Eigen::Matrix3d& l = h.linear();
    if (!orthonormal(l) || std::fabs(l(2, 1)) > 1e-9) return std::nullopt;
    Eigen::Vector3d t = h.translation();
    double h14 = t.x() + lx + l(0, 2) * lz;
    double h24 = t.y() + ly + l(1, 2) * lz;
    double h34 = t.z() + l(2, 2) * lz;
    Pose5 p;
    p.b = std::atan2(-l(2, 0), l(2, 2)) / kDeg;
    double c = std::atan2(-l(0, 1), l(1, 1));
    p.c = c / kDeg;
    p.x = h14 * std::cos(c) + h24 * std::sin(c) - lx;
    p.y = -h14 * std::sin(c) + h24 * std::cos(c) - ly;
    p.z = h34 - lz;
    return p;
}

}  // namespace pupitre::kin
