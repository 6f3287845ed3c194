#pragma once
// Tooth-pair compliance models on involute teeth described by their thickness function
// (any origin: the generated profile of lib/geometry, or a closed form in tests).
// SI units (m, N, Pa, rad).
#include "analytical/compliance.h"
#include "analytical/corner.h"
#include "analytical/elastic.h"
#include "analytical/mesh_cycle.h"

#include <array>
#include <string>
#include <vector>

namespace gearfem::analytical
{
  /// An involute tooth: the cantilever (thickness function, root and rim radii) and the
  /// involute that carries the contact.
  struct InvoluteTooth
  {
    ToothBeam beam;
    double rb = 0;    ///< base radius [m]
    double psi_b = 0; ///< half tooth thickness angle at the base circle [rad]
    double r_tip = 0; ///< tip radius [m]
  };

  /// The load of a contact at radius r on the involute of `tooth` (normal force along the
  /// line of action): phi_F = tan(alpha_r) - psi_b, contact height r cos(gamma) - r_f,
  /// half thickness r sin(gamma), gamma = psi_b - inv(alpha_r), rho = rb tan(alpha_r).
  ToothLoad involute_load(const InvoluteTooth &tooth, double r);

  enum class StiffnessModel
  {
    weber_cornell,   ///< beam + O'Donnell foundation + Weber Hertz (load dependent)
    potential_energy ///< beam + Sainsot foundation + constant Hertz (Yang & Lin, Tian)
  };
  StiffnessModel stiffness_model_from_string(const std::string &s);
  const char *to_string(StiffnessModel m);

  struct PairModelOptions
  {
    StiffnessModel model = StiffnessModel::weber_cornell;
    PlaneCondition plane = PlaneCondition::plane_stress;
    ODonnellConstant odonnell = ODonnellConstant::cornell_50_over_3pi;
    int table_points = 241; ///< positions along the line of action where the tooth parts are tabulated
  };

  /// Line-of-action data of an external pair (distances from T1) [m].
  struct PairLine
  {
    double rb1 = 0, rb2 = 0;
    double length = 0;       ///< T1T2 = a sin(alpha_w)
    double g_A = 0, g_C = 0, g_E = 0;
    double base_pitch = 0;
    // For the corner contact outside A..E (corner.h); 0 where unknown.
    double center_distance = 0;          ///< a [m]
    double r_tip1 = 0, r_tip2 = 0;       ///< tip radii [m]
    double r_form1 = 0, r_form2 = 0;     ///< start of the involute flanks (end of the fillets) [m]
    double rounding1 = 0, rounding2 = 0; ///< tip rounding radii [m] (0: sharp corners)
  };

  /// The corner-contact geometry of a pair line. With no tip rounding the corners are the
  /// ends of the involutes at E and A; with a rounding the tip radii must be set.
  CornerGeometry corner_geometry(const PairLine &line);

  /// Compliance of one tooth pair as a function of contact position g and load F. The
  /// load-independent tooth parts (beam, foundation) are computed once on a grid of
  /// `table_points` along [g_A, g_E] and interpolated (Catmull-Rom); the Hertz part is
  /// evaluated exactly at each call.
  class PairCompliance
  {
  public:
    PairCompliance(InvoluteTooth pinion, InvoluteTooth gear, const Material &m1,
                   const Material &m2, double face_width, const PairLine &line,
                   const PairModelOptions &options = {});

    /// Parts at contact position g (pinion roll distance from T1) under load F [m/N].
    struct Parts
    {
      double beam1, foundation1, beam2, foundation2, hertz;
      double total() const { return beam1 + foundation1 + beam2 + foundation2 + hertz; }
    };
    Parts parts(double g, double F) const;
    /// The same with the Hertz term for the given radii of curvature of the pinion and gear
    /// profiles at the contact [m] (a corner rounding on a mating involute) instead of the
    /// involute radii g and T1T2 - g; the tooth parts and Weber depths at g.
    Parts parts(double g, double F, double rho1, double rho2) const;
    /// Hertz half-width [m] of the involute contact at g under normal load F.
    double hertz_half_width(double g, double F) const;
    /// Exact parts (no table), for testing the table.
    Parts parts_exact(double g, double F) const;
    double operator()(double g, double F) const { return parts(g, F).total(); }
    /// The MeshModel for the load-sharing solver (holds a copy of this object); with
    /// `with_corners`, also the corner contacts OA/BΓ outside A..E (corner.h, the gear held
    /// and the pinion turned), whose compliance is taken at the nearest end of the path.
    MeshModel mesh_model(bool with_corners = false) const;

    const PairLine &line() const { return line_; }
    const PairModelOptions &options() const { return opt_; }

  private:
    double interpolate(int k, double g) const;
    double weber_depth(int i, double g) const;
    double hertz(double g, double F, double h1, double h2) const;
    double hertz_radii(double F, double rho1, double rho2, double h1, double h2) const;
    std::array<InvoluteTooth, 2> t_;
    PlaneElastic e1_, e2_;
    double b_;
    PairLine line_;
    PairModelOptions opt_;
    std::vector<double> grid_;
    std::array<std::vector<double>, 6> table_; // beam1, found1, beam2, found2, Weber depths h1, h2
  };
} // namespace gearfem::analytical
