#pragma once
// The frictionless contact problem of the Moving Spherical Tool (moving_sphere_contact.hpp) solved
// exactly: normal forces P >= 0 with gaps after the step w = M P + q >= 0 and P_i w_i = 0 (a
// linear complementarity problem; M the points' normal compliance, symmetric positive
// semi-definite; q the gaps the step would leave without contact). It is the minimum of
// 1/2 P^T M P + q^T P over P >= 0, found by a primal active-set method (Lawson and Hanson's NNLS
// steps on the quadratic): points enter the active set where the gap is most negative, and leave
// it when their force would turn negative; each set's forces come from an LDL^T solve of M on the
// set. It ends in a finite number of sets. Projected Gauss-Seidel sweeps, the method for the
// frictional problem, crawl where points lie close together and M is nearly singular.
#include <Eigen/Core>

namespace spifit::contact {

struct NormalContactSolution {
  Eigen::VectorXd force;     // P >= 0, one per point
  int active_sets = 0;       // sets solved
  bool converged = false;    // within max_sets, all gaps >= -tolerance
};

// M (k x k) and q (k); points whose M_ii <= 0 (on supported nodes only) get no force. tolerance:
// on the gaps [mm]. Deterministic.
NormalContactSolution solve_normal_contact(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, double tolerance, int max_sets);

}  // namespace spifit::contact
