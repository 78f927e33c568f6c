#pragma once
// Small dense 3x3 algebra for the singular-point search: the inverse of a Hessian (the
// Krawczyk preconditioner, Newton steps) and the eigenvalues of a symmetric one (the
// signature that tells a node, A1, from a degenerate singularity).
#include <array>
#include <optional>

namespace zs {

using Mat3 = std::array<std::array<double, 3>, 3>;

// Nothing when the matrix is singular or too ill-conditioned to invert usefully
// (|det| below 1e-14 of the product of its row norms).
std::optional<Mat3> inverse(const Mat3& m);

// Eigenvalues of the symmetric part of m, ascending (cyclic Jacobi rotations).
std::array<double, 3> eigenvalues(const Mat3& m);

}  // namespace zs
