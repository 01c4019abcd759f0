// A solid point's derivative pass on the narrow Jets (one to four parameters) against the same
// pass on the full eight slots: the same derivatives bit for bit, along a path that yields,
// reverses and moves the back-stress, with the consistent tangent's derivatives.
#include "forward/element/solid_point.hpp"
#include "tests/support/hex_elements.hpp"
#include "tests/support/path_seeds.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace spifit::element {
namespace {

using spifit::element::test::aa3003_af;
using spifit::test::path_seeds;

// The log strain at step n of a path that stretches, shears and then reverses.
Voigt6 path_strain(int n) {
  const double t = n <= 6 ? n / 6.0 : (12 - n) / 6.0 - 0.4;
  Voigt6 e;
  e << 0.03 * t, -0.012 * t, -0.014 * t, 0.02 * t, -0.006 * t, 0.004 * t;
  return e;
}

struct PathRecord {
  std::vector<SolidPointDerivatives> committed;
  std::vector<Voigt6S> pseudo_stress;
};

// The point along the path with `count` of the path seeds, the law narrowed when `narrow`.
PathRecord run_path(int count, bool narrow) {
  const material::MaterialParams<double> p = aa3003_af();
  std::vector<material::FieldSeed> seeds = path_seeds(p);
  seeds.resize(static_cast<std::size_t>(count));
  material::ReturnMappingOptions o;
  o.single_jet_evaluation = true;
  const SolidSensitivityLaw law(material::seeded_params(p, seeds), o, narrow ? count : material::kSensitivitySlots);
  EXPECT_EQ(narrow && count <= 2, law.two != nullptr);
  EXPECT_EQ(narrow && count > 2 && count <= 4, law.four != nullptr);
  const SolidPoint::Law plain(p);
  SolidPoint point(plain);
  point.enable_sensitivities();
  PathRecord out;
  for (int n = 1; n <= 12; ++n) {
    const Voigt6 eps = path_strain(n);
    Voigt6 T;
    Voigt6x6 D;
    EXPECT_TRUE(point.update_log(eps, &T, &D).ok);
    // The log strain's derivatives: a fixed pattern in the run's slots.
    SensColumns6 deps = SensColumns6::Zero();
    for (int k = 0; k < count; ++k) deps.col(k) = eps * (0.1 * (k + 1)) + Voigt6::Constant(1e-4 * n);
    Voigt6S Tp;
    EXPECT_TRUE(point.sensitivities(law, eps, nullptr, &Tp).ok);
    EXPECT_TRUE(point.sensitivities(law, eps, &deps, nullptr).ok);
    point.commit();
    out.committed.push_back(point.committed_derivatives());
    out.pseudo_stress.push_back(Tp);
  }
  EXPECT_GT(point.committed().eqps, 0.01);
  return out;
}

void expect_same(const PathRecord& a, const PathRecord& b) {
  ASSERT_EQ(a.committed.size(), b.committed.size());
  for (std::size_t n = 0; n < a.committed.size(); ++n) {
    const SolidPointDerivatives &x = a.committed[n], &y = b.committed[n];
    EXPECT_EQ(x.stress, y.stress) << "step " << n;
    EXPECT_EQ(x.plastic_strain, y.plastic_strain) << "step " << n;
    EXPECT_EQ(x.back_stress, y.back_stress) << "step " << n;
    EXPECT_EQ(x.eqps, y.eqps) << "step " << n;
    EXPECT_EQ(x.plastic_work, y.plastic_work) << "step " << n;
    EXPECT_EQ(x.tangent, y.tangent) << "step " << n;
    for (int i = 0; i < 6; ++i) {
      EXPECT_EQ(a.pseudo_stress[n](i).a, b.pseudo_stress[n](i).a);
      EXPECT_EQ(a.pseudo_stress[n](i).v, b.pseudo_stress[n](i).v) << "step " << n << ", component " << i;
    }
  }
}

TEST(SolidPointSensitivity, NarrowJetsGiveTheFullJetsDerivatives) {
  for (int count : {1, 2, 3, 4}) {
    SCOPED_TRACE(count);
    const PathRecord narrow = run_path(count, true), full = run_path(count, false);
    expect_same(narrow, full);
    // Not all zero: the slots carry derivatives.
    EXPECT_GT(full.committed.back().stress.col(count - 1).norm(), 0.0);
    EXPECT_GT(full.committed.back().tangent.col(0).norm(), 0.0);
  }
}

TEST(SolidPointSensitivity, ALawSeededBeyondItsCountIsRefused) {
  const material::MaterialParams<double> p = aa3003_af();
  EXPECT_THROW(SolidSensitivityLaw(material::seeded_params(p, path_seeds(p)), {}, 2), std::logic_error);
}

}  // namespace
}  // namespace spifit::element
