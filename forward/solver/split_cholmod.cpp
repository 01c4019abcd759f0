#include "forward/solver/split_cholmod.hpp"

#include <cholmod.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "forward/runtime/blas_threads.hpp"
#include "forward/runtime/serial_openmp_scope.hpp"
#include "forward/solver/cholmod_views.hpp"

namespace spifit::solver {

namespace {

// Runs fn(0) and fn(1), side by side when two threads are available and the BLAS may be
// called from both at once (runtime/blas_threads.hpp). CHOLMOD's own parallel
// regions inside fn must run on the calling thread (SerialOpenMpScope says why): with two
// threads, max-active-levels 1 makes them inactive; with one, no team is opened at all (a
// team of one is not an active level, so CHOLMOD would open its four threads inside it).
template <class Fn>
void for_both_halves(Fn&& fn) {
#ifdef _OPENMP
  if (omp_get_max_threads() >= 2 && runtime::blas_allows_concurrent_calls()) {
    const int saved = omp_get_max_active_levels();
    omp_set_max_active_levels(1);
#pragma omp parallel for num_threads(2) schedule(static, 1)
    for (int h = 0; h < 2; ++h) fn(h);
    omp_set_max_active_levels(saved);
    return;
  }
#endif
  const runtime::SerialOpenMpScope serial;
  fn(0);
  fn(1);
}

// One half K_h = K[D_h + S, D_h + S]: its own pattern, CHOLMOD workspace and factor.
struct Half {
  Half() {
    cholmod_l_start(&common);
    common.print = 0;
    common.supernodal = CHOLMOD_SUPERNODAL;
  }
  ~Half() {
    if (factor) cholmod_l_free_factor(&factor, &common);
    cholmod_l_finish(&common);
  }
  Half(const Half&) = delete;
  Half& operator=(const Half&) = delete;

  cholmod_common common;
  cholmod_factor* factor = nullptr;
  long n = 0, nd = 0;                // unknowns of the half and of its domain (the first nd)
  std::vector<long> global;          // local unknown -> unknown of K
  std::vector<long> ptr, idx;        // the half's pattern, both triangles
  std::vector<long> gather;          // value k of the half = value gather[k] of K
  std::vector<double> values;
  PermutedLower permuted;            // what the factorisations get (permuted_lower.hpp)
  std::vector<long> separator_at;    // pivot nd + j of L -> separator index
  Eigen::MatrixXd lcc;               // ns x ns, lower: the separator block of L, pivot order
  Eigen::MatrixXd lcc_gram;          // lower part of lcc lcc^T

  // Forward substitution of [b_D; 0]; returns w = L^-1 P [b_D; 0] (pivot order).
  bool forward(const Eigen::VectorXd& b, Eigen::VectorXd* w) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
    const long* perm = permuted.perm.data();
    for (long k = 0; k < n; ++k)
      if (perm[k] < nd) y(k) = b(global[static_cast<std::size_t>(perm[k])]);
    return substitute(CHOLMOD_L, &y, w);
  }
  bool substitute(int system, Eigen::VectorXd* rhs, Eigen::VectorXd* out) {
    cholmod_dense B = column_view(rhs->data(), rhs->size());
    cholmod_dense* X = cholmod_l_solve(system, factor, &B, &common);
    if (!X) return false;
    const double* xv = static_cast<const double*>(X->x);
    out->resize(n);
    for (long k = 0; k < n; ++k) (*out)(k) = xv[k];
    cholmod_l_free_dense(&X, &common);
    return true;
  }
};

class SplitCholmod final : public LinearSolver {
 public:
  SplitCholmod() {
    cholmod_l_start(&common_);
    common_.print = 0;
  }
  ~SplitCholmod() override { cholmod_l_finish(&common_); }

  bool factorize(const SparseMatrix& a) override {
    const auto& p = a.pattern();
    if (pattern_ != &p || nnz_ != p.nonzeros()) {
      if (!analyse(p)) return false;
      pattern_ = &p;
      nnz_ = p.nonzeros();
      ++symbolic_;
    }
    if (whole_) {  // no useful separator: one piece
      ++numeric_;
      if (!whole_->factorize(a)) return fail(whole_->error());
      error_.clear();
      return true;
    }
    const std::vector<double>& kv = a.values();
    std::array<bool, 2> ok{false, false};
    factored_ = false;
    for_both_halves([&](int h) {
      Half& half = *halves_[static_cast<std::size_t>(h)];
      half.permuted.gather(kv.data());
      cholmod_sparse A = lower_csc_view(half.permuted);
      const int st = cholmod_l_factorize(&A, half.factor, &half.common);
      ok[static_cast<std::size_t>(h)] = st && half.common.status != CHOLMOD_NOT_POSDEF;
      if (!ok[static_cast<std::size_t>(h)]) return;
      extract_separator_block(&half);
      half.lcc_gram.setZero(ns_, ns_);
      half.lcc_gram.selfadjointView<Eigen::Lower>().rankUpdate(half.lcc);
    });
    ++numeric_;
    if (!ok[0] || !ok[1]) return fail("matrix not positive definite (CHOLMOD); use UMFPACK for this tangent");
    // Schur complement on the separator: G_0 + G_1 - C (lower part), in separator order.
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(ns_, ns_);
    for (const auto& [i, j, k] : separator_entries_) s(i, j) -= kv[static_cast<std::size_t>(k)];
    for (const auto& hp : halves_) {
      const Half& half = *hp;
      for (long c = 0; c < ns_; ++c) {
        const long sc = half.separator_at[static_cast<std::size_t>(c)];
        for (long r = c; r < ns_; ++r) {
          const long sr = half.separator_at[static_cast<std::size_t>(r)];
          if (sr >= sc) s(sr, sc) += half.lcc_gram(r, c);
          else s(sc, sr) += half.lcc_gram(r, c);
        }
      }
    }
    schur_.compute(s);  // reads the lower triangle
    if (schur_.info() != Eigen::Success) return fail("matrix not positive definite (separator of the split CHOLMOD); use UMFPACK for this tangent");
    factored_ = true;
    error_.clear();
    return true;
  }

  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) override {
    if (whole_) {
      if (!whole_->solve(b, x)) return fail(whole_->error());
      return true;
    }
    if (!factored_) return fail("solve before factorize");
    std::array<Eigen::VectorXd, 2> w;
    std::array<Eigen::VectorXd, 2> t;
    std::array<bool, 2> ok{false, false};
    for_both_halves([&](int h) {
      const auto hh = static_cast<std::size_t>(h);
      Half& half = *halves_[hh];
      ok[hh] = half.forward(b, &w[hh]);
      if (ok[hh]) t[hh] = half.lcc.triangularView<Eigen::Lower>() * w[hh].tail(ns_);
    });
    if (!ok[0] || !ok[1]) return fail("CHOLMOD solve failed (split)");
    // Separator: S x_s = b_s + sum_h L_cc,h w_h,s.
    Eigen::VectorXd g(ns_);
    for (long i = 0; i < ns_; ++i) g(i) = b(separator_[static_cast<std::size_t>(i)]);
    for (std::size_t h = 0; h < 2; ++h)
      for (long j = 0; j < ns_; ++j) g(halves_[h]->separator_at[static_cast<std::size_t>(j)]) += t[h](j);
    const Eigen::VectorXd xs = schur_.solve(g);
    x->resize(b.size());
    for (long i = 0; i < ns_; ++i) (*x)(separator_[static_cast<std::size_t>(i)]) = xs(i);
    for_both_halves([&](int h) {
      const auto hh = static_cast<std::size_t>(h);
      Half& half = *halves_[hh];
      // Back substitution of [w_D; L_cc^T x_s]: L^T [x_D; x_s] = that (pivot order).
      Eigen::VectorXd xs_pivot(ns_);
      for (long j = 0; j < ns_; ++j) xs_pivot(j) = xs(half.separator_at[static_cast<std::size_t>(j)]);
      Eigen::VectorXd v = w[hh];
      v.tail(ns_) = half.lcc.triangularView<Eigen::Lower>().transpose() * xs_pivot;
      Eigen::VectorXd u;
      ok[hh] = half.substitute(CHOLMOD_Lt, &v, &u);
      if (!ok[hh]) return;
      const long* perm = half.permuted.perm.data();
      for (long k = 0; k < half.n; ++k)
        if (perm[k] < half.nd) (*x)(half.global[static_cast<std::size_t>(perm[k])]) = u(k);
    });
    if (!ok[0] || !ok[1]) return fail("CHOLMOD solve failed (split)");
    return true;
  }

  std::string layout() const override {
    if (whole_ || !halves_[0]) return "one piece";
    return "split: domains of " + std::to_string(halves_[0]->nd) + " and " + std::to_string(halves_[1]->nd) +
           " unknowns, separator of " + std::to_string(ns_);
  }

 private:
  bool fail(const std::string& m) {
    error_ = m;
    return false;
  }

  bool analyse(const SparsePattern& p) {
    whole_.reset();
    halves_ = {};
    factored_ = false;
    const long n = p.rows;
    if (n < kSplitCholmodMinUnknowns) {
      whole_ = make_one_piece_cholmod();
      return true;
    }
    cholmod_sparse A = symmetric_csc_view(n, p.row_ptr.data(), p.cols.data(), nullptr);  // the pattern
    std::vector<long> part(static_cast<std::size_t>(n), 0);
    long ns = -1;
    {
      const runtime::SerialOpenMpScope serial;
      ns = cholmod_l_bisect(&A, nullptr, 0, 1, part.data(), &common_);
    }
    const long n0 = std::count(part.begin(), part.end(), 0L), n1 = std::count(part.begin(), part.end(), 1L);
    if (ns <= 0 || n0 == 0 || n1 == 0) {  // disconnected or no split: one piece
      whole_ = make_one_piece_cholmod();
      return true;
    }
    // No entry may couple the two domains (the separator's definition).
    for (long r = 0; r < n; ++r)
      for (long k = p.row_ptr[static_cast<std::size_t>(r)]; k < p.row_ptr[static_cast<std::size_t>(r) + 1]; ++k) {
        const long pr = part[static_cast<std::size_t>(r)], pc = part[static_cast<std::size_t>(p.cols[static_cast<std::size_t>(k)])];
        if (pr != 2 && pc != 2 && pr != pc) return fail("split CHOLMOD: the bisector left an entry between the two domains");
      }
    ns_ = ns;
    separator_.clear();
    std::vector<long> sep_index(static_cast<std::size_t>(n), -1);
    for (long r = 0; r < n; ++r)
      if (part[static_cast<std::size_t>(r)] == 2) {
        sep_index[static_cast<std::size_t>(r)] = static_cast<long>(separator_.size());
        separator_.push_back(r);
      }
    separator_entries_.clear();
    for (long i = 0; i < ns_; ++i) {
      const long r = separator_[static_cast<std::size_t>(i)];
      for (long k = p.row_ptr[static_cast<std::size_t>(r)]; k < p.row_ptr[static_cast<std::size_t>(r) + 1]; ++k) {
        const long j = sep_index[static_cast<std::size_t>(p.cols[static_cast<std::size_t>(k)])];
        if (j >= 0 && j <= i) separator_entries_.push_back({i, j, k});  // lower triangle
      }
    }
    for (int h = 0; h < 2; ++h) {
      auto half = std::make_unique<Half>();
      if (!build_half(p, part, h, half.get())) return false;
      halves_[static_cast<std::size_t>(h)] = std::move(half);
    }
    return true;
  }

  bool build_half(const SparsePattern& p, const std::vector<long>& part, int h, Half* half) {
    const long n = p.rows;
    std::vector<long> local(static_cast<std::size_t>(n), -1);
    for (long r = 0; r < n; ++r)
      if (part[static_cast<std::size_t>(r)] == h) {
        local[static_cast<std::size_t>(r)] = static_cast<long>(half->global.size());
        half->global.push_back(r);
      }
    half->nd = static_cast<long>(half->global.size());
    for (long i = 0; i < ns_; ++i) local[static_cast<std::size_t>(separator_[static_cast<std::size_t>(i)])] = half->nd + i;
    half->global.insert(half->global.end(), separator_.begin(), separator_.end());
    half->n = static_cast<long>(half->global.size());
    half->ptr.assign(1, 0);
    std::vector<std::pair<long, long>> row;  // (local column, position in K)
    for (long i = 0; i < half->n; ++i) {
      const long r = half->global[static_cast<std::size_t>(i)];
      row.clear();
      for (long k = p.row_ptr[static_cast<std::size_t>(r)]; k < p.row_ptr[static_cast<std::size_t>(r) + 1]; ++k) {
        const long c = local[static_cast<std::size_t>(p.cols[static_cast<std::size_t>(k)])];
        if (c >= 0) row.emplace_back(c, k);
      }
      std::sort(row.begin(), row.end());
      for (const auto& [c, k] : row) {
        half->idx.push_back(c);
        half->gather.push_back(k);
      }
      half->ptr.push_back(static_cast<long>(half->idx.size()));
    }
    half->values.assign(half->idx.size(), 1.0);
    // Ordering: constrained AMD with the separator last, then CHOLMOD's analysis of it.
    cholmod_sparse A = symmetric_csc_view(half->n, half->ptr.data(), half->idx.data(), half->values.data());
    std::vector<long> member(static_cast<std::size_t>(half->n), 0), perm(static_cast<std::size_t>(half->n), 0);
    for (long i = half->nd; i < half->n; ++i) member[static_cast<std::size_t>(i)] = 1;
    const runtime::SerialOpenMpScope serial;
    if (!cholmod_l_camd(&A, nullptr, 0, member.data(), perm.data(), &half->common))
      return fail("split CHOLMOD: constrained ordering failed");
    half->common.nmethods = 1;
    half->common.method[0].ordering = CHOLMOD_GIVEN;
    for (const int postorder : {1, 0}) {
      half->common.postorder = postorder;
      if (half->factor) cholmod_l_free_factor(&half->factor, &half->common);
      half->factor = cholmod_l_analyze_p(&A, perm.data(), nullptr, 0, &half->common);
      if (!half->factor) return fail("split CHOLMOD: symbolic analysis failed");
      const long* lp = static_cast<const long*>(half->factor->Perm);
      bool last = true;
      for (long k = half->nd; k < half->n; ++k) last = last && lp[k] >= half->nd;
      if (last) {
        half->separator_at.resize(static_cast<std::size_t>(ns_));
        for (long j = 0; j < ns_; ++j) half->separator_at[static_cast<std::size_t>(j)] = lp[half->nd + j] - half->nd;
        half->permuted = permuted_lower(half->n, half->ptr.data(), half->idx.data(), half->gather.data(), lp);
        cholmod_l_free_factor(&half->factor, &half->common);
        half->factor = analyse_as_ordered(half->permuted, &half->common);
        if (!half->factor) return fail("split CHOLMOD: symbolic analysis of the permuted half failed");
        return true;
      }
    }
    return fail("split CHOLMOD: the analysis did not keep the separator last");
  }

  // The separator block of the supernodal factor (pivots nd..n-1) as a dense lower matrix.
  void extract_separator_block(Half* half) const {
    const cholmod_factor* L = half->factor;
    half->lcc.setZero(ns_, ns_);
    const long* super = static_cast<const long*>(L->super);
    const long* pi = static_cast<const long*>(L->pi);
    const long* px = static_cast<const long*>(L->px);
    const long* ls = static_cast<const long*>(L->s);
    const double* lx = static_cast<const double*>(L->x);
    for (long s = static_cast<long>(L->nsuper) - 1; s >= 0; --s) {
      const long k1 = super[s], k2 = super[s + 1];
      if (k2 <= half->nd) break;  // supernodes are in pivot order: the rest is domain only
      const long nsrow = pi[s + 1] - pi[s];
      for (long j = std::max(k1, half->nd); j < k2; ++j)
        for (long i = j - k1; i < nsrow; ++i) {
          const long r = ls[pi[s] + i];
          half->lcc(r - half->nd, j - half->nd) = lx[px[s] + i + (j - k1) * nsrow];
        }
    }
  }

  cholmod_common common_;
  const SparsePattern* pattern_ = nullptr;
  long nnz_ = -1, ns_ = 0;
  std::unique_ptr<LinearSolver> whole_;
  std::array<std::unique_ptr<Half>, 2> halves_;
  std::vector<long> separator_;                       // separator index -> unknown of K
  std::vector<std::array<long, 3>> separator_entries_;  // (i, j, position in K), i >= j, inside C
  Eigen::LLT<Eigen::MatrixXd> schur_;
  bool factored_ = false;
};

}  // namespace

std::unique_ptr<LinearSolver> make_split_cholmod() { return std::make_unique<SplitCholmod>(); }

}  // namespace spifit::solver
