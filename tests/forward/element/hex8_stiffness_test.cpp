// The one-point hexahedron's small-strain core: uniform gradient, hourglass operator, the
// incompatible-modes stabilisation. Patch test on distorted elements, zero-energy modes, and
// 3D pure bending with one element through the thickness against the exact solution, with
// compressible and nearly incompressible material, beside the full-integration element.
#include "forward/element/hex8_stiffness.hpp"
#include "tests/support/hex_elements.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

namespace spifit::element {
namespace {

constexpr double kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};

HexCorners box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  HexCorners X;
  for (int I = 0; I < 8; ++I)
    for (int k = 0; k < 3; ++k) X[static_cast<std::size_t>(I)](k) = kCorner[I][k] < 0 ? lo(k) : hi(k);
  return X;
}

HexCorners distorted() {
  HexCorners X = box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.0, 1.5, 1.0));
  X[2] += Eigen::Vector3d(0.3, 0.2, -0.1);
  X[5] += Eigen::Vector3d(-0.2, 0.1, 0.15);
  X[7] += Eigen::Vector3d(0.1, -0.25, 0.2);
  return X;
}

HexVector linear_field(const HexCorners& X, const Eigen::Vector3d& c, const Eigen::Matrix3d& A) {
  HexVector u;
  for (int I = 0; I < 8; ++I) u.segment<3>(3 * I) = c + A * X[static_cast<std::size_t>(I)];
  return u;
}

using test::zero_eigenvalues;

TEST(Hex8Stiffness, UniformGradientReproducesLinearFieldsAndTheVolume) {
  const HexCorners X = distorted();
  const HexUniformGradient g = hex_uniform_gradient(X);
  Eigen::Matrix3d grad_x = Eigen::Matrix3d::Zero();  // sum_I b(:, I) x_I^T = identity
  for (int I = 0; I < 8; ++I) grad_x += g.b.col(I) * X[static_cast<std::size_t>(I)].transpose();
  EXPECT_LT((grad_x - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_LT(g.b.rowwise().sum().norm(), 1e-15);
  EXPECT_NEAR(hex_uniform_gradient(box(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(3, 3.5, 4))).volume, 2.0 * 1.5 * 1.0, 1e-14);
  HexCorners inverted = X;
  std::swap(inverted[1], inverted[3]);
  EXPECT_THROW(hex_uniform_gradient(inverted), std::invalid_argument);
}

TEST(Hex8Stiffness, HourglassOperatorIgnoresLinearFieldsAndMeasuresHourglassModes) {
  const HexCorners X = distorted();
  const HexUniformGradient g = hex_uniform_gradient(X);
  const auto G = hex_hourglass_operator(X, g);
  Eigen::Matrix3d A;
  A << 0.3, -0.1, 0.2, 0.05, -0.4, 0.1, 0.25, 0.15, 0.35;
  EXPECT_LT((G * linear_field(X, Eigen::Vector3d(1, -2, 0.5), A)).norm(), 1e-14);
  const HexCorners P = box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.0, 1.5, 1.0));
  EXPECT_LT((hex_hourglass_operator(P, hex_uniform_gradient(P)) * hex_hourglass_shapes() - Eigen::Matrix<double, 12, 12>::Identity()).norm(), 1e-14);
}

TEST(Hex8Stiffness, ZeroEnergyModes) {
  const Voigt6Matrix D = isotropic_elasticity(70000.0, 0.33);
  for (const HexCorners& X : {box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.0, 1.5, 1.0)), distorted()}) {
    EXPECT_EQ(zero_eigenvalues(hex_one_point_stiffness(X, D)), 18);  // 6 rigid + 12 hourglass
    EXPECT_EQ(zero_eigenvalues(hex_incompatible_modes_stiffness(X, D)), 6);
    EXPECT_EQ(zero_eigenvalues(hex_one_point_stiffness(X, D) + hex_stabilisation_stiffness(X, D)), 6);
    EXPECT_EQ(zero_eigenvalues(hex_full_stiffness(X, D)), 6);
  }
}

TEST(Hex8Stiffness, StabilisationLeavesConstantStrainAlone) {
  const Voigt6Matrix D = isotropic_elasticity(70000.0, 0.33);
  const HexCorners X = distorted();
  Eigen::Matrix3d A;
  A << 1e-3, 2e-4, -3e-4, 0.0, -5e-4, 1e-4, 4e-4, 0.0, 2e-4;
  const HexVector u = linear_field(X, Eigen::Vector3d(0.1, 0.2, 0.3), A);
  const HexMatrix Ks = hex_stabilisation_stiffness(X, D);
  EXPECT_LT((Ks * u).norm(), 1e-12 * Ks.norm() * u.norm());
  // The one-point forces of a constant strain are V B^T D eps, the full integration's.
  const HexMatrix K1 = hex_one_point_stiffness(X, D), Kf = hex_full_stiffness(X, D);
  EXPECT_LT((K1 * u - Kf * u).norm(), 1e-10 * (Kf * u).norm());
}

// Structured blocks of nx x ny x nz hexahedra over [0, L] x [-b/2, b/2] x [-h/2, h/2]; interior
// nodes optionally moved (distorted patch). Node id i + (nx + 1) (j + (ny + 1) k).
struct Block {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 8>> hexes;
  int nx, ny, nz;
  int id(int i, int j, int k) const { return i + (nx + 1) * (j + (ny + 1) * k); }
  bool on_boundary(int n) const {
    const int i = n % (nx + 1), j = (n / (nx + 1)) % (ny + 1), k = n / ((nx + 1) * (ny + 1));
    return i == 0 || i == nx || j == 0 || j == ny || k == 0 || k == nz;
  }
};

Block block(double L, double b, double h, int nx, int ny, int nz) {
  Block B{{}, {}, nx, ny, nz};
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) B.nodes.emplace_back(L * i / nx, -0.5 * b + b * j / ny, -0.5 * h + h * k / nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        B.hexes.push_back({B.id(i, j, k), B.id(i + 1, j, k), B.id(i + 1, j + 1, k), B.id(i, j + 1, k), B.id(i, j, k + 1),
                           B.id(i + 1, j, k + 1), B.id(i + 1, j + 1, k + 1), B.id(i, j + 1, k + 1)});
  return B;
}

using ElementStiffness = HexMatrix (*)(const HexCorners&, const Voigt6Matrix&);

HexMatrix stabilised(const HexCorners& X, const Voigt6Matrix& D) { return hex_one_point_stiffness(X, D) + hex_stabilisation_stiffness(X, D); }

// Solves K u = f with u prescribed at the nodes where `fixed` is true (values from exact; f empty:
// no load); returns the largest nodal error against exact over all nodes.
double solve_against(const Block& B, const Voigt6Matrix& D, ElementStiffness stiffness, const std::function<bool(int)>& fixed,
                     const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& exact, Eigen::VectorXd f = {}) {
  const int n = static_cast<int>(B.nodes.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (const auto& h : B.hexes) {
    HexCorners X;
    for (int I = 0; I < 8; ++I) X[static_cast<std::size_t>(I)] = B.nodes[static_cast<std::size_t>(h[static_cast<std::size_t>(I)])];
    const HexMatrix Ke = stiffness(X, D);
    for (int I = 0; I < 8; ++I)
      for (int J = 0; J < 8; ++J) K.block<3, 3>(3 * h[static_cast<std::size_t>(I)], 3 * h[static_cast<std::size_t>(J)]) += Ke.block<3, 3>(3 * I, 3 * J);
  }
  std::vector<int> free, prescribed;
  for (int a = 0; a < n; ++a)
    for (int c = 0; c < 3; ++c) (fixed(a) ? prescribed : free).push_back(3 * a + c);
  Eigen::VectorXd up(static_cast<Eigen::Index>(prescribed.size()));
  for (std::size_t p = 0; p < prescribed.size(); ++p) up(static_cast<Eigen::Index>(p)) = exact(B.nodes[static_cast<std::size_t>(prescribed[p] / 3)])(prescribed[p] % 3);
  const Eigen::MatrixXd Kff = K(free, free), Kfp = K(free, prescribed);
  if (f.size() == 0) f = Eigen::VectorXd::Zero(3 * n);
  const Eigen::VectorXd uf = Kff.ldlt().solve(f(free) - Kfp * up);
  double err = 0.0;
  for (std::size_t i = 0; i < free.size(); ++i)
    err = std::max(err, std::abs(uf(static_cast<Eigen::Index>(i)) - exact(B.nodes[static_cast<std::size_t>(free[i] / 3)])(free[i] % 3)));
  return err;
}

// The hourglass stiffness's derivatives along several directions of the modulus at once, against
// central differences of hex_hourglass_stiffness: a modulus that is not symmetric (as a consistent
// tangent with kinematic hardening is) and directions that are not either, on a distorted element.
TEST(Hex8Stiffness, HourglassStiffnessDerivativesMatchCentralDifferences) {
  const HexCorners X = distorted();
  Voigt6Matrix D = isotropic_elasticity(70000.0, 0.33);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) D(i, j) += 3000.0 * u(rng);
  std::vector<Voigt6Matrix> directions;
  for (int k = 0; k < 3; ++k) {
    Voigt6Matrix d;
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) d(i, j) = 1000.0 * u(rng);
    directions.push_back(d);
  }
  directions.push_back(isotropic_elasticity(1000.0, 0.0));  // along d/dE of an isotropic modulus
  const std::vector<Eigen::Matrix<double, 12, 12>> exact = hex_hourglass_stiffness_derivatives(X, D, directions);
  ASSERT_EQ(exact.size(), directions.size());
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const double h = 1e-3;  // D moves by about 1e-5 of itself: round-off and truncation near 1e-9
    const Eigen::Matrix<double, 12, 12> cd =
        (hex_hourglass_stiffness(X, D + h * directions[k]) - hex_hourglass_stiffness(X, D - h * directions[k])) / (2.0 * h);
    const double scale = cd.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0.0);
    std::printf("direction %zu: largest difference %.2e of the largest entry\n", k, (exact[k] - cd).cwiseAbs().maxCoeff() / scale);
    EXPECT_LT((exact[k] - cd).cwiseAbs().maxCoeff(), 1e-8 * scale) << "direction " << k;
    EXPECT_LT((hex_hourglass_stiffness_derivative(X, D, directions[k]) - exact[k]).cwiseAbs().maxCoeff(), 1e-12 * scale) << k;
  }
}

TEST(Hex8Stiffness, DistortedPatchReproducesALinearField) {
  Block B = block(2.0, 2.0, 2.0, 2, 2, 2);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shift(-0.2, 0.2);
  for (int n = 0; n < static_cast<int>(B.nodes.size()); ++n)
    if (!B.on_boundary(n)) B.nodes[static_cast<std::size_t>(n)] += Eigen::Vector3d(shift(rng), shift(rng), shift(rng));
  Eigen::Matrix3d A;
  A << 1e-3, 2e-4, -3e-4, 0.0, -5e-4, 1e-4, 4e-4, 0.0, 2e-4;
  const auto exact = [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(A * x); };
  const Voigt6Matrix D = isotropic_elasticity(70000.0, 0.33);
  const auto boundary = [&](int n) { return B.on_boundary(n); };
  EXPECT_LT(solve_against(B, D, &stabilised, boundary, exact), 1e-15);
}

// Pure bending about y with curvature k: u = (k x z, -nu k y z, -k (x^2 + nu (z^2 - y^2)) / 2),
// sigma_xx = E k z and no other stress. The root x = 0 held at the exact values, the tip x = L
// loaded by the consistent nodal forces of sigma_xx (+-E k b h^2 / 24 at each corner), every
// other node free: the largest nodal error over the tip deflection k L^2 / 2.
double bending_error(ElementStiffness stiffness, double nu, int nx) {
  const double L = 10.0, b = 1.0, h = 1.0, k = 1e-3, E = 70000.0;
  const Block B = block(L, b, h, nx, 1, 1);
  const auto exact = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(k * x.x() * x.z(), -nu * k * x.y() * x.z(), -0.5 * k * (x.x() * x.x() + nu * (x.z() * x.z() - x.y() * x.y())));
  };
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(B.nodes.size()));
  for (int n = 0; n < static_cast<int>(B.nodes.size()); ++n) {
    const Eigen::Vector3d& x = B.nodes[static_cast<std::size_t>(n)];
    if (x.x() == L) f(3 * n) = (x.z() > 0 ? 1.0 : -1.0) * E * k * b * h * h / 24.0;
  }
  const auto root = [&](int n) { return B.nodes[static_cast<std::size_t>(n)].x() == 0.0; };
  return solve_against(B, isotropic_elasticity(E, nu), stiffness, root, exact, f) / (0.5 * k * L * L);
}

TEST(Hex8Stiffness, PureBendingWithOneElementThroughTheThicknessIsExact) {
  for (double nu : {0.0, 0.3, 0.4999}) {
    const double stab = bending_error(&stabilised, nu, 10);
    const double full = bending_error(&hex_full_stiffness, nu, 10);
    const double im = bending_error(&hex_incompatible_modes_stiffness, nu, 10);
    std::printf("pure bending, 10 x 1 x 1 elements, nu = %g: largest nodal error / tip deflection: one-point stabilised %.1e, "
                "incompatible modes %.1e, full integration %.1e\n", nu, stab, im, full);
    // Exact up to round-off, which grows with the bulk over the shear modulus, ~ 1 / (1 - 2 nu).
    const double roundoff = 1e-12 / (1.0 - 2.0 * nu);
    EXPECT_LT(stab, roundoff);
    EXPECT_LT(im, roundoff);
    EXPECT_GT(full, 0.1);  // the displacement element locks in shear (and in volume as nu -> 1/2)
  }
}

}  // namespace
}  // namespace spifit::element
