#pragma once
// Robust tip-relief optimisation with the FE model in the loop.
//
// Design variables: amount C_a and length L (along the line of action, from the tip) of a
// linear or parabolic tip relief, the same on both gears (2 variables) or per gear (4).
// Objective: the peak-to-peak static transmission error, or the amplitude of its first
// mesh harmonic, over one mesh cycle at each of the study torques, combined by their maximum
// or weighted mean (robust relief: Tavakoli & Houser 1986; Palmer & Fish 2010).
//
// The model is built once from the unrelieved gears, with the reliefs applied as gap
// modifications (Contact/Micro-geometry = gap, GearContactModel::set_micro_geometry): an
// evaluation re-targets the model and runs the sweep; nothing is re-meshed or
// re-factorised, and the flexibility columns cached by earlier evaluations are re-used.
// The optimisers are those of optimisers.h on the variables scaled to [0, 1].
// SI inside; micrometres for STE figures and objectives.
#include "solve/input.h"
#include "geometry/parameters.h"
#include "optimise/optimisers.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::condensed
{
  struct CondensedCycle;
}

namespace gearfem::optimise
{
  enum class ReliefMeasure
  {
    peak_to_peak,  ///< max - min of STE over the cycle
    first_harmonic ///< amplitude of the first mesh harmonic of STE (2 |DFT_1| / N)
  };
  enum class TorqueAggregate
  {
    maximum,      ///< the worst torque
    weighted_mean ///< sum w_k m_k / sum w_k
  };
  const char *to_string(ReliefMeasure m);
  const char *to_string(TorqueAggregate a);

  /// What is optimised: the variables, their box, the torques and the objective.
  struct ReliefProblem
  {
    geometry::TipRelief::Kind kind = geometry::TipRelief::Kind::linear;
    bool per_gear = false;        ///< false: one relief on both gears (C_a, L); true: (C_a1, L1, C_a2, L2)
    double amount_min = 0;        ///< [m]; an amount below 1 nm is no relief
    double amount_max = 30e-6;    ///< [m]
    double length_min = 0.5e-3;   ///< [m], > 0
    double length_max = 8e-3;     ///< [m], below the roll length of the flank
    std::vector<double> start;    ///< [m], n_variables() values; empty = the middle of the box
    std::vector<double> torques = {340.0}; ///< pinion torques [N m]
    std::vector<double> weights;  ///< one per torque (weighted mean); empty = equal
    ReliefMeasure measure     = ReliefMeasure::peak_to_peak;
    TorqueAggregate aggregate = TorqueAggregate::maximum;
    int positions   = 20;         ///< equally spaced over one mesh cycle (one angular pitch) from A
    int grid_points = 0;          ///< per variable, of the grid run on the same model (0: none)
    /// Also optimise at each torque alone (same method, start and budget, same model): the
    /// single-load optima the robust one is compared with. Needs 2 or more torques.
    bool single_torque_optima = false;
    /// Torques [N m] at which no relief, the optimum, the single-load optima and the grid's
    /// best are evaluated after the optimisation (robust.csv); empty = none.
    std::vector<double> check_torques;

    int n_variables() const { return per_gear ? 4 : 2; }
    std::vector<double> lower() const; ///< [m]
    std::vector<double> upper() const; ///< [m]
    std::vector<double> start_point() const; ///< `start`, or the middle of the box
    /// "C_a", "L" or "C_a1", "L1", "C_a2", "L2".
    std::vector<std::string> variable_names() const;
    /// Ranges and sizes; InputError naming "Optimise/Tip relief/<entry>" (exit status 2).
    void check() const;
    /// The same variables and measure at torques `t` alone: no weights (maximum), no grid,
    /// no single-load optima, no check torques.
    ReliefProblem at_torques(const std::vector<double> &t) const;
  };

  /// STE of one design over the cycle at each torque, and its objective.
  struct ReliefResult
  {
    bool ok = false;
    std::string failure;                  ///< the SolverError of a failed sweep
    double objective = 0;                 ///< [um] (0 when !ok: never NaN)
    std::vector<double> peak_to_peak;     ///< per torque [um]
    std::vector<double> harmonic;         ///< first mesh harmonic per torque [um]
    std::vector<double> mean;             ///< mean STE per torque [um]
    std::vector<std::vector<double>> ste; ///< [torque][position] [um]
    double seconds = 0;                   ///< wall time of the sweep
  };

  /// The pair of `geometry` with the relief of design vector x (SI). Throws InputError.
  geometry::GeometryInput relief_geometry(const geometry::GeometryInput &geometry, const ReliefProblem &p,
                                          const std::vector<double> &x);

  /// The reliefs at the corners of the box can be built on the pair (InputError naming
  /// "Optimise/Tip relief/Maximum length" or "Minimum length" otherwise).
  void check_relief_geometry(const geometry::GeometryInput &geometry, const ReliefProblem &p);

  /// Peak-to-peak, first harmonic and mean of an STE cycle sampled at equal steps [any unit].
  void cycle_measures(const std::vector<double> &ste, double &peak_to_peak, double &harmonic, double &mean);

  /// The FE model, built once; each evaluation only re-targets its micro-geometry and sweeps.
  class ReliefModel
  {
  public:
    /// `in`: the parsed `gearfem solve` sections (mesh, material, FE, contact; its pair and
    /// Solve section are not used). `geometry`: the macro-geometry (its reliefs ignored).
    /// Meshes and factorises the unrelieved gears (Contact/Micro-geometry is forced to gap).
    /// `condensed`: evaluate designs on a condensed cycle of the model (condensed/cycle.h),
    /// built here over the problem's positions for the torques of the problem and its check
    /// torques (at their geometric mean): a design then costs milliseconds instead of a
    /// sweep, within 0.1 % of the full FE; an evaluation the cycle cannot serve (contact
    /// beyond its candidates) falls back to the full sweep.
    ReliefModel(const geometry::GeometryInput &geometry, const solve::GearContactInput &in,
                const ReliefProblem &problem, bool condensed = false);
    ~ReliefModel();
    /// STE cycles of design x [m] at the problem's torques; a solver failure gives ok = false.
    ReliefResult evaluate(const std::vector<double> &x) { return evaluate(x, problem_); }
    /// The same at the torques, measure and aggregate of `p`, which must have the model's
    /// variables and positions (std::invalid_argument otherwise): e.g. problem().at_torques().
    ReliefResult evaluate(const std::vector<double> &x, const ReliefProblem &p);
    const ReliefProblem &problem() const { return problem_; }
    const std::vector<double> &positions() const { return positions_; } ///< roll angles [rad]
    /// Mesh, assembly and factorisation time [s]: spent once, in the constructor (an
    /// evaluation never re-enters those timer sections).
    double setup_seconds() const;
    int evaluations() const { return evaluations_; }
    /// Evaluations that fell back from the condensed cycle to the full sweep.
    int fallbacks() const { return fallbacks_; }
    /// The condensed cycle, when the model evaluates on one (null otherwise).
    const condensed::CondensedCycle *cycle() const { return cycle_.get(); }
    const contact::GearContactModel &model() const { return *model_; }

  private:
    geometry::GeometryInput geometry_;
    ReliefProblem problem_;
    /// The unrelieved pair the model was meshed from, and the design it was last re-targeted
    /// to (kept alive while the model points to it).
    std::unique_ptr<geometry::GearPair> base_pair_, current_;
    std::unique_ptr<contact::GearContactModel> model_;
    std::vector<double> positions_;
    int evaluations_ = 0, fallbacks_ = 0;
    std::unique_ptr<condensed::CondensedCycle> cycle_;
    /// STE [um] of `pair` at torque T over the positions on the cycle; false when it cannot.
    bool condensed_cycle_ste(const geometry::GearPair &pair, double T, std::vector<double> &ste) const;
  };

  /// One FE evaluation of a run.
  struct ReliefRow
  {
    int evaluation = 0;        ///< 1-based, in the order run
    std::vector<double> x;     ///< [m]
    ReliefResult result;
    double best = 0;           ///< best objective so far in this run [um]
    double seconds = 0;        ///< wall time since the start of the run
  };

  /// An optimiser run or a grid on the model.
  struct ReliefRun
  {
    std::string name;          ///< the method, or "grid NxN"
    std::vector<double> torques; ///< of its evaluations (the problem's) [N m]
    std::vector<ReliefRow> history;
    int best = -1;             ///< row of the best successful evaluation (-1: none)
    double seconds = 0;
    std::string stop_reason;
    const ReliefRow &best_row() const { return history.at(best); }
  };

  /// Minimise from the problem's start point with `settings` (method, evaluation budget,
  /// tolerances; Bound is not used: the box is the problem's). Repeated points are not
  /// re-solved. Throws SolverError when the start point's sweep fails (exit 3), InputError
  /// for bad settings. `out`: progress lines (i/N, ETA), may be null.
  ReliefRun optimise_relief(ReliefModel &model, const ReliefProblem &p, const OptimiserSettings &settings,
                            std::ostream *out);
  /// The full-factorial grid of `points` values per variable over the box (a Harris-map
  /// grid), on the same model. Failed points are recorded, not fatal.
  ReliefRun relief_grid(ReliefModel &model, const ReliefProblem &p, int points, std::ostream *out);

  /// A single-load optimum: the optimiser at one torque alone, and its optimum evaluated at
  /// all the study's torques (objective, p-p and H1 comparable with the robust optimum's).
  struct ReliefSingleLoad
  {
    double torque = 0;         ///< [N m]
    ReliefRun run;             ///< name "<method> at T N m"
    ReliefResult at_study;     ///< run.best_row().x at the study's torques and objective
  };

  /// One design evaluated at the check torques.
  struct ReliefCheck
  {
    std::string design;        ///< "no relief", "optimum", "optimum at T N m", "grid best"
    std::vector<double> x;     ///< [m]
    ReliefResult result;       ///< at ReliefProblem::check_torques (objective: their maximum)
  };

  /// Optimise at each torque of p alone (ReliefProblem::at_torques), from p's start with the
  /// same settings, on the same model. Each optimum is then evaluated at all of p's torques.
  std::vector<ReliefSingleLoad> single_load_optima(ReliefModel &model, const ReliefProblem &p,
                                                   const OptimiserSettings &settings, std::ostream *out);
  /// Each named design at `torques` on the same model (one sweep each). A failed sweep is
  /// recorded (ok = false), not fatal.
  std::vector<ReliefCheck> check_designs(ReliefModel &model, const ReliefProblem &p,
                                         const std::vector<std::pair<std::string, std::vector<double>>> &designs,
                                         const std::vector<double> &torques, std::ostream *out);

  /// A tip-relief study: the problem, the optimiser, and what optimum.prm is made from.
  struct ReliefStudy
  {
    ReliefProblem problem;
    OptimiserSettings optimiser;
    geometry::GeometryInput geometry;
    std::shared_ptr<const solve::GearContactInput> input;
    /// The `gearfem solve` case of design x (a complete .prm text).
    std::function<std::string(const std::vector<double> &)> solve_case;
    /// Evaluate designs on a condensed cycle (`Optimise/Condensed cycle = auto`).
    bool condensed = true;
  };

  struct ReliefStudyResult
  {
    ReliefRow unrelieved;   ///< reference: no relief
    ReliefRun optimiser;
    ReliefRun grid;         ///< empty history when no grid was asked
    std::vector<ReliefSingleLoad> single; ///< ReliefProblem::single_torque_optima
    std::vector<ReliefCheck> check;       ///< at ReliefProblem::check_torques
    double setup_seconds = 0;
    /// The designs were evaluated on a condensed cycle built in `cycle_seconds` [s];
    /// `fallbacks` of them fell back to the full FE sweep.
    bool condensed = false;
    double cycle_seconds = 0;
    int fallbacks = 0;
  };

  /// Build the model, evaluate the unrelieved pair, optimise, run the grid, the single-load
  /// optima and the check at other torques if asked.
  ReliefStudyResult run_relief_study(const ReliefStudy &s, std::ostream *out);
  /// Files (atomically): optimise.csv (history of optimiser and grid), ste.csv (the cycles of
  /// no relief, the start, the optimum and the grid's best at each torque), summary.md,
  /// optimum.prm (`gearfem solve` runs it), and robust.csv with check torques.
  void write_relief_study(const ReliefStudy &s, const ReliefStudyResult &r, const std::filesystem::path &dir);
  /// robust.csv: `design,<variables>,torque [N m],ok,p-p [um],H1 [um],mean STE [um],sweep
  /// time [s]`, one row per design of ReliefStudyResult::check and check torque.
  void write_check_csv(const ReliefStudy &s, const ReliefStudyResult &r, const std::filesystem::path &file);
  /// The summary table (console and summary.md).
  void print_relief_summary(const ReliefStudy &s, const ReliefStudyResult &r, std::ostream &out);
} // namespace gearfem::optimise
