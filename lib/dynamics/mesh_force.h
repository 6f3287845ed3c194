#pragma once
// Mesh-force laws of a spur gear pair, all behind one interface (MeshForceLaw), and the
// contact logic with backlash that turns a one-flank law into the force of the pair:
//   s = 1 (drive contact, delta > 0), 0 (gap, -b < delta <= 0), -1 (back contact, delta <= -b)
// (Gkimisis 2019, eqs. 4.9-4.11; Kahraman & Singh 1990, JSV 142(1), eq. 3).
// Units: theta = pinion roll angle [rad] (0 at the pitch point C), delta = compression
// along the line of action [m], force [N]. In the dimensionless Kahraman-Singh mode the
// same code runs with dimensionless numbers (period 2 pi, backlash 2, mean stiffness 1).
#include "io/mesh_table.h"

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace gearfem::dynamics
{
  /// Force on one flank set: F(theta, delta) for delta >= 0. Must also return a smooth
  /// extension for delta < 0 (used only inside a step while the contact mode is frozen).
  class MeshForceLaw
  {
  public:
    virtual ~MeshForceLaw() = default;
    virtual std::string name() const = 0;
    /// Mesh period in theta [rad] (2 pi / z1).
    virtual double period() const = 0;
    /// Positions in [0, period) where the law jumps in theta (tooth-pair entry/exit),
    /// sorted. The integrator locates these as events. Empty for continuous laws.
    virtual std::vector<double> breaks() const { return {}; }
    /// Force [N] at theta [rad], compression delta [m]; `zone` is the frozen interval
    /// index (interval j = [breaks[j-1], breaks[j]) modulo the period).
    virtual double force(double theta, double delta, int zone) const = 0;
    /// Mean mesh stiffness kbar over one period at the nominal load [N/m].
    virtual double mean_stiffness() const = 0;
    /// Evaluations outside the law's validity range (tables); 0 for closed forms.
    virtual long out_of_range_count() const { return 0; }
    /// True when the force does not depend on theta (a conservative spring: the energy
    /// balance of MeshModel::conservative() applies).
    virtual bool position_independent() const { return false; }
    /// True if the law carries its own reverse-flank (back contact) branch and backlash
    /// (a two-sided mesh table); the contact logic then uses reverse_force() and backlash()
    /// instead of mapping the drive law onto the coast flank.
    virtual bool has_reverse_branch() const { return false; }
    /// Force magnitude [N] on the coast flank at pinion roll angle theta [rad] (not mapped)
    /// and coast compression delta_r = -delta - b >= 0 [m] (laws with a reverse branch).
    virtual double reverse_force(double /*theta*/, double /*delta_r*/) const { return 0.0; }
    /// Total clearance b along the line of action of a two-sided law [m]; < 0: none.
    virtual double backlash() const { return -1.0; }
    virtual std::unique_ptr<MeshForceLaw> clone() const = 0;
  };

  /// Interval index, previous and next break of theta for a list of breaks (period p).
  struct ZoneInfo
  {
    int zone = 0;
    double prev = -1e300, next = 1e300; ///< absolute theta of the surrounding breaks [rad]
  };
  ZoneInfo locate_zone(const std::vector<double> &breaks, double period, double theta);

  /// Kahraman & Singh (1990) Fourier stiffness: F = kbar [1 + sum_n (a_n cos(n z theta) +
  /// b_n sin(n z theta))] delta. With z = 1, kbar = 1, a = (-0.2, -0.1, -0.05) this is the
  /// reference set k(t) = 1 - 0.2 cos Wt - 0.1 cos 2Wt - 0.05 cos 3Wt.
  class FourierStiffnessLaw : public MeshForceLaw
  {
  public:
    /// @param kbar mean stiffness [N/m]; @param z1 pinion teeth (period 2 pi/z1);
    /// @param a, b cosine and sine coefficients relative to kbar [-].
    FourierStiffnessLaw(double kbar, int z1, std::vector<double> a, std::vector<double> b = {});
    std::string name() const override { return "Fourier"; }
    double period() const override { return period_; }
    double force(double theta, double delta, int) const override;
    double stiffness(double theta) const;
    double mean_stiffness() const override { return kbar_; }
    bool position_independent() const override;
    const std::vector<double> &cos_coefficients() const { return a_; }
    const std::vector<double> &sin_coefficients() const { return b_; }
    std::unique_ptr<MeshForceLaw> clone() const override
    {
      return std::make_unique<FourierStiffnessLaw>(*this);
    }

  private:
    double kbar_, period_;
    int z_;
    std::vector<double> a_, b_;
  };

  /// Piecewise-constant stiffness: k_double while two pairs are in contact, k_single
  /// while one is. One mesh period starting at the start of contact A (theta_A < 0):
  /// double pair on [theta_A, theta_A + (eps - 1) p), single on [.., theta_A + p), with
  /// p = 2 pi / z1 and eps the transverse contact ratio (1 <= eps < 2).
  class PiecewiseConstantLaw : public MeshForceLaw
  {
  public:
    /// @param k_single, k_double [N/m]; @param z1; @param contact_ratio eps [-];
    /// @param theta_A roll angle of the start of active profile A [rad] (< 0).
    PiecewiseConstantLaw(double k_single, double k_double, int z1, double contact_ratio,
                         double theta_A);
    std::string name() const override { return "piecewise constant"; }
    double period() const override { return period_; }
    std::vector<double> breaks() const override { return breaks_; }
    double force(double theta, double delta, int zone) const override
    {
      return k_[zone] * delta;
    }
    double stiffness_in_zone(int zone) const { return k_[zone]; }
    double mean_stiffness() const override;
    /// Number of pairs in contact at theta (1 or 2).
    int pairs_in_contact(double theta) const;
    std::unique_ptr<MeshForceLaw> clone() const override
    {
      return std::make_unique<PiecewiseConstantLaw>(*this);
    }

  private:
    double period_, eps_, theta_A_;
    std::vector<double> breaks_;
    std::vector<double> k_; ///< per zone of breaks_
    std::vector<int> pairs_;
    double k_single_, k_double_;
  };

  // The mesh-table type belongs to the file contract (lib/io/mesh_table.h); dynamics reads it.
  using io::MeshTable;
  using io::second_axis_name;
  using io::second_axis_unit;
  using io::value_axis_unit;
  using io::value_quantity;

  enum class ThetaInterpolation
  {
    linear,         ///< bilinear in (theta, delta)
    monotone_cubic  ///< Fritsch-Carlson (1980) monotone cubic Hermite in theta, linear in delta
  };

  /// Table law: F(theta, delta) = T(theta, delta)/r_b1, periodic in theta. A k(theta, F)
  /// table is converted at construction to F on a common delta grid (delta = F/k, monotone).
  /// Outside the delta range the stiffness is clamped (linear extrapolation with the
  /// last secant); such evaluations are counted and reported.
  class TableLaw : public MeshForceLaw
  {
  public:
    /// A two-sided torque table gives a law with a reverse branch (has_reverse_branch()).
    TableLaw(const MeshTable &table, ThetaInterpolation interpolation);
    TableLaw(const TableLaw &other);
    bool has_reverse_branch() const override { return reverse_ != nullptr; }
    double reverse_force(double theta, double delta_r) const override
    {
      return reverse_ ? reverse_->force(theta, delta_r, 0) : 0.0;
    }
    double backlash() const override { return backlash_; }
    std::string name() const override { return "table"; }
    double period() const override { return period_; }
    double force(double theta, double delta, int) const override;
    double mean_stiffness() const override { return kbar_; }
    /// Mean secant stiffness at the static force F [N]: mean over theta of F/delta(theta, F).
    double mean_secant_stiffness(double F) const;
    /// Use mean_secant_stiffness(F) as the mean stiffness (damping, natural frequency);
    /// the default is the mean secant at the middle of the delta axis.
    void set_reference_load(double F) { kbar_ = mean_secant_stiffness(F); }
    long out_of_range_count() const override
    {
      return out_.load(std::memory_order_relaxed) + (reverse_ ? reverse_->out_of_range_count() : 0);
    }
    double delta_max() const { return d_.back(); }
    std::unique_ptr<MeshForceLaw> clone() const override
    {
      return std::make_unique<TableLaw>(*this);
    }

  private:
    double interp_theta(std::size_t j, double theta) const; ///< F at column j
    ThetaInterpolation interp_;
    double period_, theta0_, dtheta_;
    std::vector<double> d_;       ///< delta grid [m], d_[0] = 0
    std::vector<double> F_;       ///< forces [N], row-major theta x delta (n_theta rows)
    std::vector<double> slope_;   ///< dF/dtheta at nodes (monotone cubic)
    std::size_t nt_ = 0;
    double kbar_ = 0;
    mutable std::atomic<long> out_{0};
    double backlash_ = -1;                ///< two-sided tables: b [m]
    std::unique_ptr<TableLaw> reverse_;   ///< two-sided tables: the coast-flank branch
  };

  /// STE excitation: F = kbar (delta - e(theta)), with e(theta) the static transmission
  /// error fluctuation (STE minus its mean) [m], periodic, linear interpolation. The
  /// classic "STE-excited" linear formulation (e.g. Ozguven & Houser 1988, JSV 121(3)).
  class SteExcitationLaw : public MeshForceLaw
  {
  public:
    /// @param kbar [N/m]; @param theta, ste nodes over one period [rad], [m]; @param period [rad]
    SteExcitationLaw(double kbar, std::vector<double> theta, std::vector<double> ste,
                     double period);
    std::string name() const override { return "STE excitation"; }
    double period() const override { return period_; }
    double force(double theta, double delta, int) const override;
    double fluctuation(double theta) const;
    double mean_stiffness() const override { return kbar_; }
    std::unique_ptr<MeshForceLaw> clone() const override
    {
      return std::make_unique<SteExcitationLaw>(*this);
    }

  private:
    double kbar_, period_;
    std::vector<double> th_, e_;
  };

  /// The force of the pair from a drive-flank law, backlash and the reverse-flank mapping.
  /// Back contact (s = -1) uses the coast law at theta_r = reverse_offset - theta with
  /// compression delta_r = -delta - b (Gkimisis 2019, 4.11); with reverse_mapping = false it
  /// uses theta itself (Kahraman & Singh's symmetric dead zone).
  struct ContactLogic
  {
    double backlash = 0;          ///< total clearance b along the line of action [m]; inf: none
    bool reverse_mapping = false; ///< reverse-flank mapping (Gkimisis 2019) on/off
    double reverse_offset = 0;    ///< theta_r = reverse_offset - theta [rad]
    /// Contact state from delta.
    int state(double delta) const { return delta > 0 ? 1 : (delta > -backlash ? 0 : -1); }
    double coast_theta(double theta) const
    {
      return reverse_mapping ? reverse_offset - theta : theta;
    }
  };
} // namespace gearfem::dynamics
