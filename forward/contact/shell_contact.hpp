#pragma once
// Contact between a rigid analytic sphere (the forming tool) and the tool-side surface of the shell
// (docs/design/contact.md, "Contact formulation (ShellContact)"; thesis §3.2, §7.1): penalty normal
// pressure p = K_p <-g> at n x n contact points per element (the mid-surface offset by h/2 along
// the director), and regularised Coulomb friction (elastic stick with a tangential penalty K_t,
// return to the cone |t| <= mu p). The contribution of an element is returned in the shell's
// p-variables (positions and directors), with its exact (non-symmetric once sliding) tangent; the
// shell's director_to_dofs turns it into nodal forces and moments.
#include "forward/element/shell_q4.hpp"
#include "forward/material/sensitivity_scalar.hpp"
#include "forward/mesh/mesh.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spifit::contact {

struct ContactOptions {
  double penalty = 1000.0;           // K_p [N/mm^3]
  double friction = 0.0;             // Coulomb coefficient mu
  double tangential_penalty = 0.0;   // K_t [N/mm^3]; 0: equal to K_p
  int points = 2;                    // contact points per direction and element (1..6)
  // Tool-side surface seen by the tool: "flat" = bilinear facets x + h/2 d; "phong" = the
  // facets curved with the nodal directors (Phong tessellation, alpha = 1/2): each point is
  // pulled towards the tangent planes of the element's nodes, which removes most of the
  // facet kinks the tool meets when it slides over element edges.
  enum class Surface { flat, phong };
  Surface surface = Surface::flat;
  // How the explicit scheme makes the contact: this penalty (penalty), or the Moving Spherical
  // Tool's forces chosen for zero penetration and exact Coulomb friction (mst, thesis §5.3;
  // model/moving_sphere_contact.hpp). Implicit runs take penalty only.
  enum class Method { penalty, mst };
  Method method = Method::penalty;
  std::string validate() const;      // empty when valid
};

struct SphereTool {
  double radius = 5.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();           // at the end of the increment
  Eigen::Vector3d centre_committed = Eigen::Vector3d::Zero(); // at its start (slip reference)
  // Tool spin over the increment: rotation vector (axis x angle, rad) about the tool centre.
  // The tool surface at a contact point x moves by spin x (x - centre) (rate form: the
  // velocity at the end of the increment times its duration), which enters the friction slip.
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();
};

// What an element's contact points carry at the trial state.
struct ContactSummary {
  Eigen::Vector3d force_on_sheet = Eigen::Vector3d::Zero();  // N
  double max_penetration = 0.0;  // mm
  double max_pressure = 0.0;     // MPa
  int active_points = 0;
  int sticking_points = 0;  // of the active ones, inside the friction cone (|t| < mu p)
};

class ShellContact {
 public:
  // Reference geometry of the contact points of every element of the mesh. `tools` > 1 keeps a
  // separate set of contact point states (pressure, friction history) for each of that many
  // tools, e.g. the real tool and its rotated copies of a pie model ("virtual tools",
  // ShellModel::set_tool_copies).
  ShellContact(const mesh::Mesh& mesh, const ContactOptions& options, int tools = 1);

  // Adds the contact of element e with tool number `tool_index` (current nodes x, directors d;
  // x0, d0 at the start of the increment, for the slip; tool-side offset `offset` = h/2) to rp
  // (forces on p) and kp (their derivative). Returns false when the element is too far from the
  // tool to touch it (nothing added). tool_index in [0, tools()). Thread-safe for distinct e.
  bool element(int e, const element::NodeVectors& x, const element::NodeVectors& d, const element::NodeVectors& x0,
               const element::NodeVectors& d0, double offset, const SphereTool& tool, element::Vec24* rp, element::Mat24* kp,
               ContactSummary* summary, int tool_index = 0);
  void commit();
  void revert();

  // Direct differentiation (docs/design/sensitivities.md). The derivative slots of the run's
  // parameters that are the contact's own: the penalty K_p (the tangential K_t too when it
  // follows K_p) and the friction coefficient mu; -1: not a parameter.
  struct ParameterSlots {
    int penalty = -1, friction = -1;
  };
  // From the next increment on, the contact points keep the derivatives of their committed
  // tangential traction (the friction's stick history). Both surfaces (flat facets and Phong's).
  void enable_sensitivities(const ParameterSlots& slots);
  // The committed traction derivatives for checkpoints, bit-exact, slots 0 .. count - 1 (the
  // others are zero); load_sensitivities resets the trial ones to them.
  void save_sensitivities(io::BinaryWriter& w, int count) const;
  void load_sensitivities(io::BinaryReader& r, int count);
  // How an element's configuration moves with the parameters (a column per slot): its trial
  // p-variables (positions and directors, 24 rows; null: held fixed, the pseudo-load), the
  // committed ones and the tool-side offset (half the committed thickness).
  struct ConfigurationDerivatives {
    const element::SensDofs* p = nullptr;
    element::SensDofs p0 = element::SensDofs::Zero();
    material::SensitivityRow offset = material::SensitivityRow::Zero();
  };
  // Adds to drp the derivative of element()'s rp (same arguments, the trial state element()
  // left: the points in contact and their stick or slip) along dc, with the parameters' own
  // slots and the committed tractions' derivatives; the derivative of the branch the run took.
  // With keep, the trial tractions' derivatives are kept for commit() (every element of the
  // mesh must then be visited, those out of reach included). Returns false when no point of the
  // element touches the tool. Thread-safe for distinct e.
  bool element_derivatives(int e, const element::NodeVectors& x, const element::NodeVectors& d, const element::NodeVectors& x0,
                           const element::NodeVectors& d0, double offset, const SphereTool& tool, const ConfigurationDerivatives& dc,
                           element::SensDofs* drp, bool keep, int tool_index = 0);
  // Committed contact point states of every tool (checkpoints, bit-exact); load_state resets
  // the trial states to them. io::ArchiveError when the counts differ from this contact's.
  void save_state(io::BinaryWriter& w) const;
  void load_state(io::BinaryReader& r);
  int tools() const { return tools_; }
  // Position of contact point p of an element (natural-coordinate shape values N) on the
  // tool-side surface of the given options: exposed for tests.
  static Eigen::Vector3d surface_point(const ContactOptions& o, const Eigen::Vector4d& N, const element::NodeVectors& x,
                                       const element::NodeVectors& d, double offset);
  // Largest penetration of the tool into an element's tool-side surface, sampled on a
  // samples x samples grid over the whole element (edges included; 0 when the tool misses it).
  // The contact points see only their own penetration: where this exceeds theirs, the tool
  // sinks between them (too few points for the element's current size; output
  // surface_penetration of the cone scenes).
  static double surface_penetration(const ContactOptions& o, const element::NodeVectors& x, const element::NodeVectors& d,
                                    double offset, const SphereTool& tool, int samples = 11);
  // A warning when the tool reached clearly deeper (above 1.5x) into the tool-side surface than
  // its points x points contact points per element felt, i.e. it sank between them; else "".
  static std::string resolution_warning(double point_depth, double surface_depth, int points);
  // A warning (empty: none) when the tool sat deeper in the sheet than a penalty contact should
  // let it: more than kPenetrationWarningFraction of the thickness. With K_p = 1e3 N/mm^3 (the
  // thesis's compromise, §7.1) the bundled indent, line and cone70 scenes reach 10-17 % of
  // their thickness, the five-stage vwall 33 % (0.50 mm of 1.5 mm), which it is told.
  static constexpr double kPenetrationWarningFraction = 0.2;
  static std::string penetration_warning(double depth, double thickness, double penalty);

  // Sum over the committed contact points of one tool (element order: deterministic), in the
  // sheet's frame.
  ContactSummary committed_summary(int tool_index = 0) const;
  // Energies of the committed state [N mm] over all tools: stored in the penalty springs
  // (normal: p g / 2 per area; tangential stick: |t|^2 / (2 K_t)), and the frictional
  // dissipation accumulated at every commit, -(t_old + t_new) / 2 . slip - the change of the
  // stick energy (a point leaving contact dissipates its stick energy).
  double stored_energy() const;
  double friction_dissipation() const { return dissipation_; }
  // Committed normal contact force on each element's points, all tools [N] (sum of p dA).
  std::vector<double> element_normal_force() const;
  // Largest committed pressure over each element's points and all tools (VTU cell data).
  std::vector<double> element_pressure() const;
  const ContactOptions& options() const { return options_; }

 private:
  struct PointState {
    Eigen::Vector3d traction = Eigen::Vector3d::Zero();  // tangential traction on the sheet [MPa]
    Eigen::Vector3d force = Eigen::Vector3d::Zero();     // force on the sheet [N]
    Eigen::Vector3d slip = Eigen::Vector3d::Zero();      // trial only: sheet relative to tool over the increment [mm]
    double pressure = 0.0, penetration = 0.0;
    bool active = false;
    bool sliding = false;  // on the friction cone (slip), or frictionless; not in checkpoints
  };
  struct PointGeometry {
    Eigen::Vector4d N;
    double area = 0.0;  // reference area weight
  };
  ContactOptions options_;
  const mesh::Mesh* mesh_;
  std::vector<PointGeometry> points_;  // one set per element (same for all, in natural coordinates) x area
  std::vector<double> areas_;          // per element x point
  std::vector<PointState> committed_, trial_;  // [tool][element][point]
  int per_element_ = 0;
  double dissipation_ = 0.0;  // committed frictional dissipation [N mm]
  int tools_ = 1;
  // With sensitivities: the slots, and each point's tangential traction derivatives (committed
  // and trial, like the states).
  using TractionDerivatives = Eigen::Matrix<double, 3, material::kSensitivitySlots>;
  ParameterSlots slots_;
  bool sensitivities_ = false;
  std::vector<TractionDerivatives> committed_dt_, trial_dt_;
};

}  // namespace spifit::contact
