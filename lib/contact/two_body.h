#pragma once
// Contact (frictionless, or with Coulomb friction along a kinematic sliding direction)
// between two linear-elastic bodies, each with its own factorised
// body-frame stiffness (fem::ElasticBody, clamped bore or edges). Body 2 is fixed; body 1
// moves rigidly by one drive coordinate q (a rotation about its centre [rad] or a
// translation along a direction [m]) applied kinematically: the rigid placement is exact
// and only the elastic part is a displacement. SI units.
//
// Formulation (node-to-segment, or with ContactOptions::gap = integrated its
// segment-to-segment variant where each slave node's gap is weighted over its slave faces;
// Wriggers, Computational Contact Mechanics, 2nd ed. 2006, ch. 4-6; piecewise-linear
// weights on quadratic faces, as quadratic mortar methods use for positive weights).
// Either body may carry slave nodes: the Scene says, per body, which surface nodes
// are slaves at this configuration (a gear pair makes the owner of a tip corner the slave
// of that tooth pair, see GearContactModel); each slave node s is checked against the
// exact curves of the other body (the master) plus its displacement interpolated by the
// face shape functions N_j. A scene with no slave masks uses ContactOptions::slave for
// every node (single pass). Normal gap
//   g_s = (x_s + u_s - x_m(t) - sum_j N_j u_j) . n
// with n the master's outward normal. Linearised about the current state:
//   g = g_hat + a q + B^T u,   u = C B lambda   =>   g = g_hat + a q + W lambda,
// where lambda_s >= 0 is the normal contact force of node s [N], B its nodal force
// directions, C = K^-1 restricted to the surface DoFs (exact flexibility of the
// factorised body, computed column by column with one block solve and cached), and
// W = B^T C B the Delassus operator. This is the exact Schur complement of the assembled
// two-body system [K B; B^T 0] on the contact unknowns: no approximation beyond the
// linearisation of the gap, which the outer loop re-evaluates on the exact geometry.
//
//  - lagrange: primal-dual active set (semismooth Newton on the NCP function
//    lambda - max(0, lambda - c g), Hintermueller, Ito & Kunisch 2002, SIAM J. Optim.
//    13(3)); stops when the active set is unchanged and the complementarity residual is
//    below tolerance.
//  - penalty: lambda_s = eps_s <-g_s>, eps_s = factor * E * b * w_s / h_s (E/h scaling);
//    Newton with the consistent tangent (W + eps^-1) on the current active set, which is
//    rebuilt whenever the set of penetrating nodes changes.
// Friction (ContactOptions::friction = mu > 0; docs/friction.md): the sliding direction at
// each gap point is that of the rigid-body velocities of the two bodies at unit drive rate
// (set_kinematics), known before the solve, so the tangential force mu lambda s, s = -sign
// of the slave's sliding velocity along t = (-n_y, n_x) (regularised below
// friction_tolerance), never changes sign between iterations. The force directions become
// B_f = B + mu B_t S and g = g_hat + a q + W_f lambda with W_f = B^T C B_f (non-symmetric);
// the load is T = -a_f^T lambda with a_f the virtual work of B_f on the drive.
// Load control (target generalised force T = -a^T lambda) adds q as an unknown to the same
// Newton system (bordered), so torque targeting is a Newton iteration with the consistent
// tangent dT/dq = a_A^T (W_AA + D)^-1 a_A, warm-started from the previous position.
#include "contact/options.h"
#include "contact/surface.h"
#include "geometry/pair.h"

#include <Eigen/Dense>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace gearfem::contact
{
  /// The rigid drive of body 1.
  struct Drive
  {
    enum class Kind
    {
      rotation,   ///< about body 1's placement centre, q in rad (counter-clockwise > 0)
      translation ///< along `direction`, q in m
    };
    Kind kind = Kind::rotation;
    Vec2 direction = Vec2(0, 1);
  };

  /// One slave node in contact (or candidate) at the solution.
  struct ContactPoint
  {
    int slave_body = 1;    ///< body carrying the slave node (1 or 2); the other is the master
    int node = -1;         ///< slave surface node (index into that body's surface)
    int slave_tooth = -1, master_tooth = -1;
    int master_piece = -1;
    double master_t = 0;
    unsigned int slave_code = 0;  ///< boundary segment code of the slave node (mesh::boundary::Code)
    unsigned int master_code = 0; ///< segment code of the master piece
    bool master_corner = false;   ///< projection at a master piece end without a tangent-continuous neighbour
    Vec2 master_point;            ///< closest point on the undeformed master, rigidly placed [m], pair frame
    /// Tooth of body `body` (1 or 2) in this pair of nodes/pieces.
    int tooth(int body) const { return body == slave_body ? slave_tooth : master_tooth; }
    Vec2 x;                ///< slave node, rigidly placed (undeformed) [m], pair frame
    Vec2 normal;           ///< master outward normal, pair frame
    double gap = 0;        ///< normal gap at the solution [m] (< 0: penalty penetration)
    double force = 0;      ///< normal force lambda >= 0 [N]
    double pressure = 0;   ///< recovered contact pressure [Pa] (ContactSurface::recover_pressure)
    double weight = 0;     ///< consistent nodal weight w [m]
    double arm = 0;        ///< a_s = dg/dq [m/rad or -]
    /// Friction force on the slave along t = (-n_y, n_x) [N] (0 when frictionless).
    double friction = 0;
    /// Rigid-body sliding velocity of the slave relative to the master along t, per unit
    /// drive rate [m/rad or -] (0 without kinematics).
    double sliding = 0;
    /// Rigid-body velocity of the slave relative to the master along the normal n, per unit
    /// drive rate, weighted like the gap [m/rad or -]: 0 at conjugate contact (involute
    /// flanks on the line of action), not at a tip corner or off the line of action; the
    /// normal force then does work, lambda * approach.
    double approach = 0;
  };

  struct ContactSolution
  {
    bool converged = false;
    double q = 0;              ///< drive coordinate [rad] or [m]
    double load = 0;           ///< generalised force on body 1, -a^T lambda [N m] or [N]
    double tangent = 0;        ///< dload/dq at the converged active set [N m/rad] or [N/m]
    std::vector<ContactPoint> points; ///< all candidate slave nodes
    int n_active = 0;
    int active_set_iterations = 0, geometry_iterations = 0, load_cuts = 0;
    double complementarity = 0;       ///< ||min(lambda, c g)|| / ||lambda|| (Lagrange)
    double max_penetration = 0;       ///< max(-g) over candidates [m]
    std::vector<std::string> history; ///< one line per geometry iteration
    /// Nodal contact forces in each body frame (DoF, value) [N].
    std::vector<std::pair<unsigned int, double>> forces[2];
    double t_search = 0, t_compliance = 0, t_solve = 0; ///< wall times [s]
  };

  /// Which nodes are slaves and which pieces may act as masters at one configuration.
  struct Scene
  {
    geometry::Placement placement[2]; ///< rigid placements at q = 0
    /// Per body: the surface nodes that are slaves (checked against the other body). Both
    /// empty: every node of ContactOptions::slave. A node should be a slave of at most one
    /// zone: two passes over the same zone over-constrain a Lagrange solve.
    std::vector<bool> slave_nodes[2];
    std::vector<bool> master_pieces[2]; ///< per body mesh piece; empty: all
  };

  enum class Control
  {
    displacement, ///< q given
    load          ///< generalised force given, q unknown
  };

  /// Material removed from a body's surface along its normal at a point of its undeformed
  /// surface (body frame) [m]: a profile modification applied as an initial separation.
  using GapModification = std::function<double(const Vec2 &x_body)>;

  struct CondensedPosition; // contact/condensed.h

  /// Rigid-body kinematics of the pair per unit drive rate, for the sliding direction of
  /// friction: body 1 moves with the drive (rotation about its placement centre, or the
  /// translation), body 2 turns about its placement centre at `omega2` per unit drive rate.
  struct SlidingKinematics
  {
    double omega2 = 0.0;         ///< [rad per unit q]; gear pair: -z1/z2 (external)
    double reference_speed = 1.0; ///< speed that scales the sliding tolerance [m per unit q]
  };

  class TwoBodyContact
  {
  public:
    TwoBodyContact(const ContactSurface &surface1, const ContactSurface &surface2,
                   const ContactOptions &options, const Drive &drive = Drive());

    /// Solve one configuration. `warm` (may be null) seeds q and the contact forces.
    /// Throws SolverError with the residual history if it does not converge after the
    /// load cuts, and SolverError("no contact") when nothing can carry a load.
    ContactSolution solve(const Scene &scene, Control control, double value,
                          const ContactSolution *warm = nullptr);

    const ContactSurface &surface(int body) const { return body == 1 ? *s1_ : *s2_; }
    /// The width the contact pressure acts over: the smaller thickness (face width) of the
    /// two bodies [m]. The wider body's extra width carries no contact (ISO 6336-2 takes the
    /// same common face width for sigma_H); recovering the pressure over the slave's own
    /// width would put it 7 % low on a 75 mm pinion against a 70 mm gear.
    double contact_width() const;
    const ContactOptions &options() const { return options_; }
    /// Number of flexibility columns computed so far per body (cache statistics).
    std::size_t cached_columns(int body) const;
    /// Rigid placement of body `body` at drive coordinate q.
    geometry::Placement placed(const Scene &scene, int body, double q) const;
    /// Add `f` (material removed, >= 0 where the surface is relieved) of body `body` to every
    /// gap measured at its points, as slave point or as master projection. Null: none.
    void set_gap_modification(int body, GapModification f);
    /// The rigid-body kinematics that set the sliding direction of friction.
    void set_kinematics(const SlidingKinematics &k) { kinematics_ = k; }
    const SlidingKinematics &kinematics() const { return kinematics_; }
    /// Change the Coulomb coefficient (e.g. a load-dependent law per torque level); [0, 1].
    void set_friction(double mu);

    /// The universe of body `body`: its contact-surface DoFs (universe index -> global DoF),
    /// on which the flexibility is cached.
    const std::vector<unsigned int> &universe(int body) const { return cache_[body - 1].dofs; }
    /// Observe linear functionals of body `body`'s displacement (rows over its global DoFs,
    /// e.g. the fillet stresses of fem::BoundaryStressFunctionals): they are evaluated on
    /// every flexibility column as it is computed (unit-load solves, no extra solve), so
    /// that observed(body) * f is their value under nodal forces f on the universe. Drops
    /// the cached columns.
    void observe(int body, const std::vector<std::vector<std::pair<unsigned int, double>>> &rows);
    /// The observed functionals per unit universe force: rows x universe [unit/N]; column j
    /// is valid once flexibility column j is computed (compute_columns).
    const Eigen::MatrixXd &observed(int body) const { return cache_[body - 1].flex->S; }
    /// The observed functionals under the nodal forces (global DoF, value) [N] of body
    /// `body`, all on its universe and with their columns computed (the forces of a solution
    /// of this solver): observed(body) * f. SolverError for a force off the computed columns.
    Eigen::VectorXd observed_response(int body, const std::vector<std::pair<unsigned int, double>> &forces) const;
    /// Compute the flexibility columns (and observed values) of universe indices `idx` now.
    void compute_columns(int body, const std::vector<int> &idx);
    /// The condensed problem of `solution`, a converged solve of `scene` by this solver
    /// (contact/condensed.h): candidates, W, a, the unmodified gap, its curvature in q, the
    /// modification samples, the force directions and the pressure recovery. Re-runs the
    /// search and linearisation at the solution's state. `band` > 0 (below the search distance)
    /// keeps only the candidates whose gap at the solution is within it, and becomes the stored
    /// search distance: the re-solve's edge check then refuses a load that closes half of it.
    CondensedPosition condense(const Scene &scene, const ContactSolution &solution, double band = 0);

  private:
    /// One point of a slave surface (a node, or a Gauss point of a slave face) projected
    /// onto the displaced master.
    struct GapPoint
    {
      int face = -1;             ///< master face
      Projection pr;             ///< closest point on the master (master body frame)
      std::vector<double> shape; ///< master face shape values at the closest point
      double g = 0;              ///< current normal gap [m]
      Vec2 n_pair;               ///< master outward normal, pair frame
      Vec2 x;                    ///< the slave point, undeformed, slave body frame
    };
    /// A Gauss point of a slave face: its gap point, the slave face and the face's shape
    /// values there, the arc-length weight ds [m], and where it lies on the node polyline
    /// of the face (between face nodes `sub` and `sub + 1`, at eta in [0, 1]).
    struct FaceSample
    {
      GapPoint gp;
      int slave_face = -1;
      std::vector<double> slave_shape;
      double ds = 0;
      int sub = 0;
      double eta = 0;
    };
    /// One slave node within the search distance of the other body.
    struct Candidate
    {
      int S = 1, node = -1;         ///< slave body, its surface node
      GapPoint at;                  ///< the node's own projection
      /// Integrated gap: (sample index, N_j(x_k) ds_k / w_j); empty: the nodal gap.
      std::vector<std::pair<int, double>> terms;
      double g = 0;                 ///< current gap (nodal or integrated) [m]
    };
    struct SearchResult
    {
      std::vector<Candidate> cand;
      std::vector<FaceSample> samples;
    };
    /// condense(): flag the stored candidates next to a slave node outside the set.
    void mark_edges(const Scene &scene, const SearchResult &sr, CondensedPosition &out) const;
    /// The contact problem linearised about the current state: g = ghat + a q + W lambda.
    struct Linearisation
    {
      std::vector<std::vector<std::pair<int, double>>> B[2]; ///< per body, per candidate: (universe index, value)
      Eigen::VectorXd a, ghat, D, lambda0;
      Eigen::MatrixXd W;
      /// With friction: the force directions B_f per body and candidate (B without), the
      /// load arm a_f (a without), and per candidate the friction factor s (tangential force
      /// mu lambda s along t) and the sliding velocity at its own projection [m per unit q].
      std::vector<std::vector<std::pair<int, double>>> F[2];
      Eigen::VectorXd af, slip, sliding;
      Eigen::VectorXd approach; ///< per candidate: n . (v_S - v_M), weighted like the gap
      const std::vector<std::vector<std::pair<int, double>>> &forces(int b) const { return F[b].empty() ? B[b] : F[b]; }
      const Eigen::VectorXd &load_arm() const { return af.size() ? af : a; }
      double t_flex = 0; ///< flexibility columns computed for it [s]
      /// Per body: the universe indices of all candidates' force directions (sorted), the
      /// rows of C that W needs, and B and the force directions in positions of that list.
      std::vector<int> support[2];
      std::vector<std::vector<std::pair<int, double>>> Bs[2], Fs[2];
      /// Candidates whose column of W (and row: W is B^T C B_f with C symmetric) is filled.
      /// W is filled on demand (fill_delassus): the complementarity solve needs only the
      /// columns of the active candidates, so the flexibility columns of a candidate that
      /// never carries a force are never computed.
      std::vector<char> filled;
      /// Per candidate: the candidates whose slave nodes share a slave face with its own (the
      /// next to enter the active set as a contact patch grows); their flexibility columns
      /// come with its own (one MUMPS request has a fixed cost of about ten columns).
      std::vector<std::vector<int>> neighbours;
    };
    /// The flexibility on the universe. A column is computed on the rows of the contact
    /// zone of its request (and of the observed functionals); later zones add their rows
    /// to it as they need them: a selected-entries request costs by its entries, and most
    /// of the universe lies far from the contact of any one position.
    struct Flexibility
    {
      Eigen::MatrixXd C;      ///< columns of K^-1 on the surface DoFs [m/N], on their filled rows
      Eigen::MatrixXd S;      ///< observed functionals of the same columns (observe)
      std::vector<char> have; ///< column computed (1)
      std::vector<char> filled; ///< entry (i, j) of C computed: filled[j * n + i]
      void reset(std::size_t n, std::size_t n_observed);
    };
    struct BodyCache
    {
      std::vector<unsigned int> dofs;             ///< universe: the surface DoFs
      std::vector<int> index;                     ///< global DoF -> universe index (-1)
      /// The flexibility on the universe [m/N] and which columns are computed; one object
      /// for both bodies when they are the same factorised body with the same surface
      /// (identical gears), so each column is solved once.
      std::shared_ptr<Flexibility> flex;
      Eigen::VectorXd u;                          ///< current elastic displacement on the zone's rows
      /// The contact zone of the configuration (set_zone): per surface node, whether it lies
      /// within reach of the other body; the universe indices of its DoFs (sorted).
      std::vector<char> node_zone;
      std::vector<int> zone;
      /// A wider zone whose rows a request fills (by twice the search distance more): the
      /// zone moves with the contact from one position to the next, and a request costs
      /// about as much as a thousand entries whatever its size.
      std::vector<int> fill_zone;
      /// Universe indices that the observed functionals read (sorted): every column fills them.
      std::vector<int> observed_universe;
      double r_max = 0; ///< largest distance of a surface node from the body's placement origin [m]
      std::vector<double> node_h;                 ///< longest face chord at each surface node [m]
      std::vector<std::vector<int>> node_faces;   ///< surface faces around each node
      std::vector<char> kink;                     ///< node at a surface end or a normal jump (a corner)
      std::vector<unsigned int> observed_dofs;    ///< support of the observed functionals
      /// Observed functionals: rows of (index into the universe followed by observed_dofs,
      /// coefficient).
      std::vector<std::vector<std::pair<int, double>>> observed_rows;
    };
    ContactSolution solve_once(const Scene &scene, Control control, double value,
                               const ContactSolution *warm);
    /// The band of solve_once's search (search) at drive value q: twice the rigid approach
    /// |q| r_max (the largest surface radius of body 1; 1 for a translation), at least a
    /// thirtieth of the search distance (10 um at the default 0.3 mm). The candidates only
    /// cut what each iteration solves: a node left out has a gap above the smallest by the
    /// band at the iteration's state, and a settled iteration moves the state by far less,
    /// so the converged solution is the one over every node within the search distance
    /// (validation/model_choice's random 1 at m/30: the same sweep.csv, 38 % less contact
    /// time, the same geometry iterations). The second half of the geometry iterations
    /// searches without a band.
    double candidate_band(double q) const;
    /// The candidates: the slave nodes of the zone within the search distance of the master,
    /// with their gaps. With `band` finite, only those whose nodal gap is within `band` of the
    /// smallest one, or that carry a force in `lambda_node` (by key; may be null) or share a
    /// face with a node that does, are kept: the others cannot touch within one iteration
    /// (candidate_band).
    SearchResult search(const Scene &scene, double q, double band = std::numeric_limits<double>::infinity(),
                        const std::vector<double> *lambda_node = nullptr) const;
    /// Project slave point xs (pair frame) onto body M's displaced master (fixed point on the
    /// master displacement). false when nothing lies within the search distance.
    /// `slave_offset`: the slave body's gap modification at the point [m].
    /// `hint_key` (>= 0) names the slave point: its last projection starts this one
    /// (ContactSurface::project_from), and this one is kept for the next.
    bool project_point(const Scene &scene, int M, const Vec2 &xs, double q, GapPoint &out,
                       double slave_offset = 0.0, long long hint_key = -1) const;
    /// Gap modification of body `body` at body-frame point x (0 without one).
    double gap_offset(int body, const Vec2 &x) const { return gap_mod_[body - 1] ? gap_mod_[body - 1](x) : 0.0; }
    /// Gauss samples of the slave faces around candidate c, and its integrated gap terms;
    /// false (nodal gap kept) where a sample has no smooth master point.
    bool integrate_gap(const Scene &scene, double q, Candidate &c, std::vector<FaceSample> &samples,
                       std::vector<int> &face_sample) const;
    /// `full`: fill every column of W (the condensed cycle stores it); otherwise only the
    /// columns of the warm start's loaded candidates, the rest on demand (fill_delassus).
    Linearisation linearise(const Scene &scene, const SearchResult &sr, double q,
                            const std::vector<double> &lambda_node, double &t_compliance, bool full);
    /// Add the gap of one slave point to row k of L (linearise): its force directions on both
    /// bodies, its load arm, approach and friction factor; `coef_sum` accumulates `coef`.
    void add_gap_point(Linearisation &L, const Scene &scene, const geometry::Placement P[2], int k, int S,
                       const GapPoint &gp, const std::vector<int> &slave_nodes,
                       const std::vector<double> &slave_shape, double coef, double &coef_sum) const;
    /// L.neighbours: per candidate, the candidates on the slave faces around its node.
    void find_neighbours(Linearisation &L, const std::vector<Candidate> &cand) const;
    /// The rows of W's columns on `L`'s support (universe indices `used`, sorted and made
    /// unique here), W zero and nothing filled.
    void prepare_delassus(Linearisation &L, std::vector<int> used[2]) const;
    /// Fill the columns and rows of the Delassus operator W (W_f with friction) of the
    /// candidates `ks` not yet filled, after computing their flexibility columns.
    void fill_delassus(Linearisation &L, const std::vector<int> &ks, double &t_compliance);
    void fill_solution(ContactSolution &out, const std::vector<Candidate> &cand,
                       const Linearisation &lin, const Eigen::VectorXd &lambda,
                       const Eigen::VectorXd &gap, const Scene &scene, double q) const;
    /// (body, node) of every slave node of the scene.
    std::vector<std::pair<int, int>> slaves(const Scene &scene) const;
    /// Index of (body, node) in the per-solve node arrays.
    int key(int body, int node) const { return body == 1 ? node : int(s1_->nodes().size()) + node; }
    /// Make the flexibility columns `universe_indices` of body `body` available on the rows
    /// of the zone, the observed functionals and `extra_rows` (universe indices): one
    /// request for what is missing.
    void ensure_columns(int body, const std::vector<int> &universe_indices, double &seconds,
                        const std::vector<int> &extra_rows = {});
    /// The contact zone at drive coordinate q: the surface nodes of each body within the
    /// search distance plus `margin` (and their face length) of the other body.
    void set_zone(const Scene &scene, double q, double margin);
    /// Whether the zone still covers every node that can come within the search distance:
    /// the drive has moved by less than the margin since set_zone, with four times the
    /// largest elastic displacement on the zone to spare.
    bool zone_holds(double q) const;
    /// u of each body from nodal forces (universe index, value), after making their columns
    /// available on the zone.
    void set_displacements(const std::vector<std::pair<int, double>> forces[2], double &seconds);
    Vec2 displacement(int body, int node) const;
    Vec2 interpolate(int body, int face, const std::vector<double> &shape) const;
    /// Rigid-body velocity of body `body` at pair-frame point x per unit drive rate.
    Vec2 rigid_velocity(const Scene &scene, int body, const Vec2 &x) const;
    /// Sliding velocity along t = (-n_y, n_x) of the slave point xs of body S relative to
    /// the master point xm in contact with it (pair frame), per unit drive rate.
    double sliding_velocity(const Scene &scene, int S, const Vec2 &xs, const Vec2 &xm, const Vec2 &n) const;

    const ContactSurface *s1_, *s2_;
    ContactOptions options_;
    Drive drive_;
    GapModification gap_mod_[2];
    SlidingKinematics kinematics_;
    BodyCache cache_[2];
    /// The last projection of each slave point (node or face sample) onto its master, the
    /// start of the next one within one configuration (cleared by solve(); search is const:
    /// a cache, not state; every projection is exact to the Newton tolerance).
    mutable std::unordered_map<long long, Projection> hints_;
    double zone_q_ = 0, zone_margin_ = 0;
    /// A projection landed on a master face with a node outside the zone (search is const).
    mutable bool zone_breach_ = false;
  };
} // namespace gearfem::contact
