// Direct differentiation through a shell section: the derivatives of the resultants along a
// path of strains against central differences of whole paths with perturbed parameters.
#include "forward/element/shell_section.hpp"
#include "forward/io/binary_archive.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "tests/support/central_differences.hpp"
#include "tests/support/hex_elements.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <vector>

namespace spifit::element {
namespace {

using material::FieldSeed;
using material::MaterialField;
using material::SensitivityRow;

// Swift K (slot 0), n (slot 1), Armstrong-Frederick CX (slot 2), E (slot 3); slot 4 is a
// parameter the strains depend on (below), not the law.
std::vector<FieldSeed> seeds(const material::MaterialParams<double>& p) {
  auto row = [](int k) { SensitivityRow r = SensitivityRow::Zero(); r(k) = 1.0; return r; };
  return {{{MaterialField::hardening, p.hardening.law, 0}, row(0)},
          {{MaterialField::hardening, p.hardening.law, 2}, row(1)},
          {{MaterialField::kinematic, p.kinematic.law, 0}, row(2)},
          {{MaterialField::E, -1, 0}, row(3)}};
}

// A bending and stretching path into plasticity, then partly back: membrane strains e and
// curvatures kappa per increment at s = 0, and their change per unit s.
struct PathPoint {
  Vec3 e, kappa, de, dkappa;
};
std::vector<PathPoint> path() {
  std::vector<PathPoint> out;
  for (int n = 1; n <= 6; ++n) {
    const double t = n <= 4 ? n / 4.0 : 1.0 - 0.3 * (n - 4);
    out.push_back({Vec3(0.03 * t, -0.01 * t, 0.004 * t), Vec3(0.08 * t, 0.01 * t, -0.02 * t), Vec3(0.01 * t, 0.002, 0.0),
                   Vec3(0.02 * t, 0.0, 0.01)});
  }
  return out;
}

std::vector<Vec6> resultants(const material::MaterialParams<double>& p, double s) {
  const material::ReturnMapping<double, 3> law(p);
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellSection sec(law, rule, 1.2);
  std::vector<Vec6> out;
  for (const PathPoint& q : path()) {
    Vec6 r;
    EXPECT_TRUE(sec.update(q.e + s * q.de, q.kappa + s * q.dkappa, &r, nullptr).ok);
    sec.commit();
    out.push_back(r);
  }
  return out;
}

TEST(ShellSectionSensitivity, ResultantsMatchCentralDifferencesAlongAPath) {
  const material::MaterialParams<double> p = test::aa3003_af();
  const material::ReturnMapping<double, 3> law(p);
  const std::vector<FieldSeed> sd = seeds(p);
  const SensLaw slaw(material::seeded_params(p, sd));
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellSection sec(law, rule, 1.2);
  sec.enable_sensitivities();
  std::vector<Eigen::Matrix<double, 6, 5>> ddm;
  for (const PathPoint& q : path()) {
    Vec6 r;
    ASSERT_TRUE(sec.update(q.e, q.kappa, &r, nullptr).ok);
    Vec3S e, kappa;
    for (int i = 0; i < 3; ++i) {
      SensitivityRow de = SensitivityRow::Zero(), dk = SensitivityRow::Zero();
      de(4) = q.de(i);
      dk(4) = q.dkappa(i);
      e(i) = material::with_derivatives(q.e(i), de);
      kappa(i) = material::with_derivatives(q.kappa(i), dk);
    }
    Vec6S rs;
    ASSERT_TRUE(sec.update_sensitivities(slaw, e, kappa, &rs).ok);
    Eigen::Matrix<double, 6, 5> d;
    for (int i = 0; i < 6; ++i) {
      EXPECT_NEAR(rs(i).a, r(i), 1e-9 * (1.0 + std::abs(r(i))));
      d.row(i) = rs(i).v.head<5>().transpose();
    }
    ddm.push_back(d);
    sec.commit();
  }
  EXPECT_GT(sec.layer_state(4).eqps, 0.01);
  // Central differences with steps h and h/4: the exact derivative lies within their own
  // spread (Richardson: error ~ h^2).
  for (int k = 0; k < 5; ++k) {
    const double h = k == 0 ? 0.5 : k == 1 ? 1e-4 : k == 2 ? 0.05 : k == 3 ? 50.0 : 1e-5;
    std::vector<Vec6> cd(path().size()), cd4(path().size());
    for (double step : {h, h / 4.0}) {
      material::MaterialParams<double> pp = p, pm = p;
      double sp = 0.0, sm = 0.0;
      if (k < 4) {
        material::material_field(pp, sd[static_cast<std::size_t>(k)].field) += step;
        material::material_field(pm, sd[static_cast<std::size_t>(k)].field) -= step;
      } else {
        sp = step;
        sm = -step;
      }
      const std::vector<Vec6> rp = resultants(pp, sp), rm = resultants(pm, sm);
      for (std::size_t n = 0; n < rp.size(); ++n) (step == h ? cd : cd4)[n] = (rp[n] - rm[n]) / (2.0 * step);
    }
    std::vector<Vec6> exact;
    for (const auto& d : ddm) exact.push_back(d.col(k));
    const double worst = spifit::test::expect_within_central_differences(exact, cd, cd4, 1e-7, "slot " + std::to_string(k));
    std::printf("slot %d: largest relative difference to central differences (h/4) %.2e\n", k, worst);
  }
}

// The one Jet pass of a run with few parameters (pseudo_resultants linearises each layer in its
// strain, advance_sensitivities applies the strains' derivatives) against the two passes of
// update_sensitivities, along the same path: the same pseudo-resultants and committed
// derivatives to round-off, since forward differentiation is linear in its seeds.
TEST(ShellSectionSensitivity, OnePassLinearisationEqualsTwoPasses) {
  const material::MaterialParams<double> p = test::aa3003_af();
  const material::ReturnMapping<double, 3> law(p);
  const SensLaw slaw(material::seeded_params(p, seeds(p)));
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellSection one(law, rule, 1.2), two(law, rule, 1.2);
  one.enable_sensitivities();
  two.enable_sensitivities();
  constexpr int kCount = 5;  // slots 5 .. 7 carry the layers' strains
  double worst = 0.0;
  for (const PathPoint& q : path()) {
    Vec6 r;
    ASSERT_TRUE(one.update(q.e, q.kappa, &r, nullptr).ok);
    ASSERT_TRUE(two.update(q.e, q.kappa, &r, nullptr).ok);
    Vec6S a, b;
    ASSERT_TRUE(one.pseudo_resultants(slaw, nullptr, q.e, q.kappa, kCount, &a).ok);
    EXPECT_TRUE(one.linearised());
    ASSERT_TRUE(two.update_sensitivities(slaw, q.e.cast<Sens>(), q.kappa.cast<Sens>(), &b).ok);
    for (int i = 0; i < 6; ++i) {
      EXPECT_TRUE(a(i).v.tail<3>().isZero(0.0));  // the strain's slots are not handed on
      for (int k = 0; k < kCount; ++k) worst = std::max(worst, std::abs(a(i).v(k) - b(i).v(k)) / (1.0 + std::abs(b(i).v(k))));
    }
    Vec3S e, kappa;
    for (int i = 0; i < 3; ++i) {
      SensitivityRow de = SensitivityRow::Zero(), dk = SensitivityRow::Zero();
      de(4) = q.de(i);
      dk(4) = q.dkappa(i);
      de(0) = 0.001 * q.de(i);  // a parameter that moves both the law and the strains
      e(i) = material::with_derivatives(q.e(i), de);
      kappa(i) = material::with_derivatives(q.kappa(i), dk);
    }
    one.advance_sensitivities(e, kappa);
    EXPECT_FALSE(one.linearised());
    ASSERT_TRUE(two.update_sensitivities(slaw, e, kappa, &b).ok);
    one.commit();
    two.commit();
    EXPECT_NEAR(one.thickness_sensitivity()(4), two.thickness_sensitivity()(4), 1e-12);
    for (int l = 0; l < one.layers(); ++l) {
      const auto &x = one.layer_state_sensitivity(l), &y = two.layer_state_sensitivity(l);
      for (int k = 0; k < kCount; ++k) {
        for (int i = 0; i < 3; ++i) {
          worst = std::max(worst, std::abs(x.stress(i).v(k) - y.stress(i).v(k)) / (1.0 + std::abs(y.stress(i).v(k))));
          worst = std::max(worst, std::abs(x.back_stress(i).v(k) - y.back_stress(i).v(k)) / (1.0 + std::abs(y.back_stress(i).v(k))));
        }
        worst = std::max(worst, std::abs(x.eqps.v(k) - y.eqps.v(k)) / (1.0 + std::abs(y.eqps.v(k))));
      }
    }
  }
  std::printf("one pass against two: largest relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-11);
  EXPECT_GT(one.layer_state(4).eqps, 0.01);
  EXPECT_THROW(one.advance_sensitivities(Vec3S::Zero(), Vec3S::Zero()), std::logic_error);  // only after pseudo_resultants
}

// A run with one parameter linearises the layers on Jets of four slots (the parameter and the
// strain's three), one with two or three on six, rather than eight, and keeps `count` derivatives
// per layer field rather than eight: the same pseudo-resultants and committed derivatives, for
// parameters of the law that also move the strains, and the same after a checkpoint.
TEST(ShellSectionSensitivity, TheNarrowPassesEqualTheFullOne) {
  const material::MaterialParams<double> p = test::aa3003_af();
  const material::ReturnMapping<double, 3> law(p);
  const ThicknessRule rule = gauss_legendre_rule(5);
  material::ReturnMappingOptions options;  // as the shell family builds its laws
  options.single_jet_evaluation = true;
  const std::vector<FieldSeed> all = seeds(p);
  EXPECT_THROW(NarrowLaws(material::seeded_params(p, all), options, 1), std::logic_error);  // seeds beyond the slots kept
  for (const int count : {1, 2, 3}) {  // swift.K; and swift.n; and af.CX
    const std::vector<FieldSeed> used(all.begin(), all.begin() + count);
    const material::MaterialParams<Sens> seeded = material::seeded_params(p, used);
    const SensLaw slaw(seeded, options);
    const NarrowLaws nlaws(seeded, options, count);
    EXPECT_EQ(nlaws.four != nullptr, count == 1);
    EXPECT_EQ(nlaws.six != nullptr, count > 1);
    ShellSection narrow(law, rule, 1.2), full(law, rule, 1.2), restored(law, rule, 1.2);
    narrow.enable_sensitivities(count);
    full.enable_sensitivities();
    restored.enable_sensitivities(count);
    EXPECT_THROW(narrow.pseudo_resultants(slaw, nullptr, Vec3::Zero(), Vec3::Zero(), count + 1, nullptr), std::logic_error);  // beyond its slots
    double worst = 0.0;
    const auto compare = [&](const Sens& a, const Sens& b) {
      for (int k = 0; k < material::kSensitivitySlots; ++k) {
        if (k >= count) {
          EXPECT_EQ(a.v(k), 0.0);
        }
        worst = std::max(worst, std::abs(a.v(k) - b.v(k)) / (1.0 + std::abs(b.v(k))));
      }
    };
    for (const PathPoint& q : path()) {
      Vec6 r;
      ASSERT_TRUE(narrow.update(q.e, q.kappa, &r, nullptr).ok);
      ASSERT_TRUE(full.update(q.e, q.kappa, &r, nullptr).ok);
      Vec6S a, b;
      ASSERT_TRUE(narrow.pseudo_resultants(slaw, &nlaws, q.e, q.kappa, count, &a).ok);
      ASSERT_TRUE(full.pseudo_resultants(slaw, nullptr, q.e, q.kappa, count, &b).ok);
      for (int i = 0; i < 6; ++i) compare(a(i), b(i));
      Vec3S e, kappa;
      for (int i = 0; i < 3; ++i) {
        SensitivityRow de = SensitivityRow::Zero(), dk = SensitivityRow::Zero();
        for (int k = 0; k < count; ++k) {
          de(k) = 1e-4 * (k + 1) * q.de(i);
          dk(k) = 1e-4 * q.dkappa(i);
        }
        e(i) = material::with_derivatives(q.e(i), de);
        kappa(i) = material::with_derivatives(q.kappa(i), dk);
      }
      narrow.advance_sensitivities(e, kappa);
      full.advance_sensitivities(e, kappa);
      narrow.commit();
      full.commit();
      // The commit's thickness on the narrow Jets against eight slots: h = h0 / sqrt(det(I + 2e)).
      const Sens c11 = 1.0 + 2.0 * e(0), c22 = 1.0 + 2.0 * e(1);
      const Sens h = 1.2 / sqrt(c11 * c22 - e(2) * e(2));
      for (int k = 0; k < material::kSensitivitySlots; ++k) {
        EXPECT_NEAR(narrow.thickness_sensitivity()(k), h.v(k), 1e-15 * (1.0 + std::abs(h.v(k))));
        EXPECT_EQ(narrow.thickness_sensitivity()(k), full.thickness_sensitivity()(k));
      }
      EXPECT_GT(std::abs(h.v(0)), 1e-7);
      for (int l = 0; l < narrow.layers(); ++l) {
        const auto &x = narrow.layer_state_sensitivity(l), &y = full.layer_state_sensitivity(l);
        for (int i = 0; i < 3; ++i) {
          compare(x.stress(i), y.stress(i));
          compare(x.plastic_strain(i), y.plastic_strain(i));
          compare(x.back_stress(i), y.back_stress(i));
        }
        compare(x.eqps, y.eqps);
        compare(x.plastic_work, y.plastic_work);
      }
    }
    // A checkpoint of the compact derivatives restores them bit for bit, and the next increment
    // from it is the same (its pseudo-resultants read every kept field, the log strains' too).
    io::BinaryWriter w("section-sensitivity-test", 1);
    narrow.save_state(w);
    narrow.save_sensitivities(w, count);
    io::BinaryReader r(w.finish(), "section-sensitivity-test", 1);
    restored.load_state(r);
    restored.load_sensitivities(r, count);
    r.finish();
    EXPECT_EQ(restored.thickness_sensitivity(), narrow.thickness_sensitivity());
    for (int l = 0; l < narrow.layers(); ++l) {
      const auto &x = restored.layer_state_sensitivity(l), &y = narrow.layer_state_sensitivity(l);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(x.stress(i).v, y.stress(i).v);
        EXPECT_EQ(x.plastic_strain(i).v, y.plastic_strain(i).v);
        EXPECT_EQ(x.back_stress(i).v, y.back_stress(i).v);
      }
      EXPECT_EQ(x.back_stress_zz.v, y.back_stress_zz.v);
      EXPECT_EQ(x.eqps.v, y.eqps.v);
      EXPECT_EQ(x.plastic_work.v, y.plastic_work.v);
    }
    const PathPoint last = path().back();
    const Vec3 e1 = 1.01 * last.e, k1 = 1.01 * last.kappa;
    Vec6 r1, r2;
    ASSERT_TRUE(narrow.update(e1, k1, &r1, nullptr).ok);
    ASSERT_TRUE(restored.update(e1, k1, &r2, nullptr).ok);
    EXPECT_EQ(r1, r2);
    Vec6S a1, a2;
    ASSERT_TRUE(narrow.pseudo_resultants(slaw, &nlaws, e1, k1, count, &a1).ok);
    ASSERT_TRUE(restored.pseudo_resultants(slaw, &nlaws, e1, k1, count, &a2).ok);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(a1(i).v, a2(i).v);
    EXPECT_GT(a1(0).v.head(count).norm(), 0.0);
    std::printf("%d of eight slots in use, narrow Jets against eight: largest relative difference %.2e\n", count, worst);
    EXPECT_LT(worst, 1e-12);
    EXPECT_GT(narrow.layer_state(4).eqps, 0.01);
    for (int k = 0; k < count; ++k) EXPECT_GT(std::abs(narrow.layer_state_sensitivity(4).eqps.v(k)), 1e-9);  // each parameter moves the state
  }
}

}  // namespace
}  // namespace spifit::element
