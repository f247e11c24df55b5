#pragma once
// Orientation conventions of ADAMS (docs/theory.md, "Frames and angles"): body-fixed 3-1-3
// Euler angles (psi, theta, phi), axis-point frames, Euler parameters.

#include <Eigen/Dense>

namespace openmss {

// A = Rz(psi) Rx(theta) Rz(phi): columns are the rotated frame's axes in the reference frame.
Eigen::Matrix3d matrixFromEuler313(double psi, double theta, double phi);
// Inverse of the above; theta in [0, pi]. At theta = 0 or pi psi and phi are not separable:
// psi takes the whole rotation and phi = 0.
Eigen::Vector3d euler313FromMatrix(const Eigen::Matrix3d& a);
// Angles (t1, t2, t3) of a body-fixed rotation sequence about axes a, b, c (0 = x, 1 = y,
// 2 = z): A = R_a(t1) R_b(t2) R_c(t3). Tait-Bryan sequences (a, b, c distinct) give
// t2 in [-pi/2, pi/2]; proper Euler sequences (a == c) give t2 in [0, pi]. At the singular
// middle angle t1 takes the whole rotation and t3 = 0.
Eigen::Vector3d bodyFixedAngles(const Eigen::Matrix3d& a, int first, int second, int third);
// ORIENT system codes 1..10 (docs/expressions.md, "ORIENT codes") as axis sequences; else false.
bool orientSequence(int code, int* first, int* second, int* third);
// ORIENT codes 1..24 as the body-fixed sequence whose angle answers ORIENT(code, component):
// codes 1..12 are the body-fixed sequences 1-2-3, 2-3-1, 3-1-2, 1-3-2, 2-1-3, 3-2-1, 1-2-1,
// 1-3-1, 2-1-2, 2-3-2, 3-1-3, 3-2-3 and codes 13..24 the space-fixed ones in the same order.
// A space-fixed a-b-c rotation by (t1, t2, t3) is R_c(t3) R_b(t2) R_a(t1), the body-fixed c-b-a
// rotation by (t3, t2, t1), so its component k (1..3) is component 4 - k of the reversed body
// sequence. *bodyComponent is 1-based. False for other codes.
bool orientBodySequence(int code, int component, int* first, int* second, int* third,
                        int* bodyComponent);

// Axis-point frame: z along (zPoint - origin); x toward xPoint, made orthogonal to z.
// Returns false when the points are degenerate (coincident or collinear).
bool matrixFromAxisPoints(const Eigen::Vector3d& origin, const Eigen::Vector3d& zPoint,
                          const Eigen::Vector3d& xPoint, bool zGiven, bool xGiven,
                          Eigen::Matrix3d* a);
// The same with USEXP (MARKER): x exactly along (xPoint - origin), zPoint only fixing the x-z
// plane (z toward it, made orthogonal to x; the reference z axis when no zPoint is given).
bool matrixFromAxisPointsUseX(const Eigen::Vector3d& origin, const Eigen::Vector3d& zPoint,
                              const Eigen::Vector3d& xPoint, bool zGiven, Eigen::Matrix3d* a);

// Unit quaternion (e0, e1, e2, e3) with e0 >= 0 of a rotation matrix (Shepperd's method).
Eigen::Vector4d quaternionFromMatrix(const Eigen::Matrix3d& a);

}  // namespace openmss
