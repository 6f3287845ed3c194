#include "solve/run.h"
#include "base/units.h"

#include "analytical/iso6336_stiffness.h"
#include "base/errors.h"
#include "base/progress.h"
#include "fem/output.h"
#include "io/journal.h"
#include "loading/sweep.h"
#include "post/observers.h"

#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace gearfem::solve
{
  using post::EvaluatingObserver;
  using post::Evaluator;
  using post::PositionObserver;
  using post::PositionResult;
  using post::PostOptions;

  namespace
  {

    int point_code(const std::string &n)
    {
      const std::string names = "ABCDE";
      const auto p            = n.size() == 1 ? names.find(n[0]) : std::string::npos;
      return p == std::string::npos ? 0 : int(p) + 1;
    }

    std::string vtu_name(double T, std::size_t i)
    {
      std::ostringstream n;
      n << "pair_T" << T << "_" << std::setw(3) << std::setfill('0') << i << ".vtu";
      return n.str();
    }

    /// Positions written as VTU under `VTU = named`: every position of a `named` run, else
    /// the positions nearest to B, C and D.
    std::set<std::size_t> named_vtu_positions(const solve::GearContactInput &in,
                                              const std::vector<std::pair<std::string, double>> &positions)
    {
      std::set<std::size_t> out;
      if (in.solve.positions == solve::SolveParameters::Positions::named)
        {
          for (std::size_t i = 0; i < positions.size(); ++i)
            out.insert(i);
          return out;
        }
      for (const char *n : {"B", "C", "D"})
        {
          const double phi = in.meshing().point(n).roll_angle;
          std::size_t best = 0;
          for (std::size_t i = 1; i < positions.size(); ++i)
            if (std::abs(positions[i].second - phi) < std::abs(positions[best].second - phi))
              best = i;
          out.insert(best);
        }
      return out;
    }

    /// Appends the rows of each finished position and remembers them for the journal.
    class TablesObserver : public PositionObserver
    {
    public:
      TablesObserver(io::SolveResults &t, double z_ratio, double face_width)
        : t_(t), z_ratio_(z_ratio), face_width_(face_width)
      {}
      void finished(const loading::SweepPoint &p, const contact::ContactState &s, PositionResult &r) override
      {
        const std::size_t s0 = t_.sweep.n_rows(), p0 = t_.pairs.n_rows(), q0 = t_.pressure.n_rows();
        append_position(t_, s, r, p.name, int(p.position_index), z_ratio_, face_width_);
        record = io::JournalRecord();
        record.index = p.index;
        for (std::size_t i = s0; i < t_.sweep.n_rows(); ++i)
          record.rows.emplace_back("sweep", t_.sweep.row(i));
        for (std::size_t i = p0; i < t_.pairs.n_rows(); ++i)
          record.rows.emplace_back("pairs", t_.pairs.row(i));
        for (std::size_t i = q0; i < t_.pressure.n_rows(); ++i)
          record.rows.emplace_back("pressure", t_.pressure.row(i));
      }
      io::JournalRecord record; ///< the rows of the last finished position

    private:
      io::SolveResults &t_;
      double z_ratio_, face_width_;
    };

    /// Writes the VTU of the selected positions and collects the PVD records.
    class VtuObserver : public PositionObserver
    {
    public:
      VtuObserver(const post::PointSolver &solver, const solve::SolveParameters &sp, std::set<std::size_t> named,
                  std::filesystem::path dir)
        : solver_(solver), sp_(sp), named_(std::move(named)), dir_(std::move(dir))
      {}
      bool wants_fields(const loading::SweepPoint &p) const override
      {
        return sp_.vtu == solve::SolveParameters::Vtu::all ||
               (sp_.vtu == solve::SolveParameters::Vtu::named && named_.count(p.position_index));
      }
      void finished(const loading::SweepPoint &p, const contact::ContactState &s, PositionResult &r) override
      {
        last_file.clear();
        if (!wants_fields(p))
          return;
        last_file = vtu_name(p.torque, p.position_index);
        post::write_vtu(*solver_.field_model(), s, r, dir_ / last_file, sp_.vtu_scale);
        pvd[p.torque].emplace_back(p.phi1 / units::deg, last_file);
        r.u[0].reinit(0), r.u[1].reinit(0);
      }
      std::map<double, std::vector<std::pair<double, std::string>>> pvd;
      std::string last_file;

    private:
      const post::PointSolver &solver_;
      const solve::SolveParameters &sp_;
      std::set<std::size_t> named_;
      std::filesystem::path dir_;
    };

    /// Appends each finished position (rows, VTU name, warm start) to the journal.
    class JournalObserver : public PositionObserver
    {
    public:
      JournalObserver(std::filesystem::path file, const TablesObserver &tables, const VtuObserver &vtu)
        : file_(std::move(file)), tables_(tables), vtu_(vtu)
      {}
      void finished(const loading::SweepPoint &, const contact::ContactState &s, PositionResult &) override
      {
        io::JournalRecord rec = tables_.record;
        rec.data["warm"]      = loading::pack_warm_start(s.solution);
        if (!vtu_.last_file.empty())
          rec.text["vtu"] = vtu_.last_file;
        io::append_journal(file_, rec);
      }

    private:
      std::filesystem::path file_;
      const TablesObserver &tables_;
      const VtuObserver &vtu_;
    };

    class ProgressObserver : public PositionObserver
    {
    public:
      /// A line every `every` points (0: every tenth of the run), and at the last.
      ProgressObserver(std::ostream *out, std::size_t total, std::size_t done, std::size_t every)
        : progress_(out, total, "position", done)
        , out_(out)
        , every_(every > 0 ? every : std::max<std::size_t>(1, total / 10))
      {}
      void finished(const loading::SweepPoint &p, const contact::ContactState &s, PositionResult &r) override
      {
        if (!out_ || ((p.index + 1) % every_ != 0 && p.index + 1 != p.total))
          return;
        std::ostringstream d;
        d << "T " << p.torque << " N m, roll " << std::fixed << std::setprecision(3) << p.phi1 / units::deg << " deg"
          << (p.name.empty() ? "" : " (" + p.name + ")") << ", STE " << std::setprecision(3) << r.ste * 1e6
          << " um, pairs " << r.n_pairs << ", " << std::setprecision(2) << s.t_contact + r.t_post << " s";
        progress_.step(p.index + 1, d.str());
      }

    private:
      Progress progress_;
      std::ostream *out_;
      std::size_t every_;
    };

    /// Calls SolveRunOptions::torque_done after the last position of each torque but the last.
    class TorqueDoneObserver : public PositionObserver
    {
    public:
      TorqueDoneObserver(const SolveRunOptions &options, const io::SolveResults &t, const post::PointSolver &solver,
                         std::size_t n_positions)
        : options_(options), t_(t), solver_(solver), n_positions_(n_positions)
      {}
      void finished(const loading::SweepPoint &p, const contact::ContactState &, PositionResult &) override
      {
        if (!options_.torque_done || p.position_index + 1 != n_positions_ || p.index + 1 == p.total)
          return;
        stop_ = !options_.torque_done(p.torque_index, t_.sweep, solver_.seconds("contact"));
      }
      bool stop_requested() const override { return stop_; }

    private:
      const SolveRunOptions &options_;
      const io::SolveResults &t_;
      const post::PointSolver &solver_;
      std::size_t n_positions_;
      bool stop_ = false;
    };

    /// Replay the journal into the tables and the PVD records; returns where to start.
    loading::SweepStart resume_from(const std::filesystem::path &journal, const io::JournalHeader &expected,
                                    io::SolveResults &t, VtuObserver &vtu,
                                    const std::vector<std::pair<std::string, double>> &positions,
                                    const std::vector<double> &torques)
    {
      io::JournalHeader h;
      const auto records = io::replay_journal(journal, h);
      if (h.kind != expected.kind || h.key != expected.key || h.total != expected.total)
        throw InputError("--resume", journal.string(),
                         "the journal of a run of this input (hash " + expected.key + ", " +
                           std::to_string(expected.total) + " positions)",
                         "it belongs to input hash " + h.key + " with " + std::to_string(h.total) +
                           " positions: the input changed; run without --resume");
      loading::SweepStart start;
      for (const auto &rec : records)
        {
          if (rec.index != start.next)
            throw InputError("--resume", journal.string(), "consecutive records",
                             "record " + std::to_string(rec.index) + " after " + std::to_string(start.next));
          for (const auto &[block, row] : rec.rows)
            {
              Table &table = block == "sweep" ? t.sweep : block == "pairs" ? t.pairs : t.pressure;
              if (row.size() != table.n_columns() || (block != "sweep" && block != "pairs" && block != "pressure"))
                throw InputError("--resume", journal.string(), "rows of the solve-results tables",
                                 "a '" + block + "' row of " + std::to_string(row.size()) + " values");
              table.add_row(row);
            }
          const auto f = rec.text.find("vtu");
          if (f != rec.text.end())
            {
              const std::size_t np = positions.size();
              vtu.pvd[torques[rec.index / np]].emplace_back(positions[rec.index % np].second / units::deg, f->second);
            }
          const auto w = rec.data.find("warm");
          start.have_warm = w != rec.data.end();
          if (start.have_warm)
            start.warm = loading::unpack_warm_start(w->second);
          ++start.next;
        }
      io::rewrite_journal(journal, h, records); // drop a record a kill may have cut short
      return start;
    }
  } // namespace

  void append_position(io::SolveResults &t, const contact::ContactState &state, const PositionResult &r,
                       const std::string &name, int index, double z_ratio, double face_width)
  {
    const double deg = 180 / units::pi;
    const auto &s    = state.solution;
    auto width       = [&](double k) { return k / (face_width * 1e3) * 1e-6; }; // N/m -> N/(mm um)
    double share     = 0;
    for (const auto &p : r.pairs)
      share = std::max(share, p.share);
    t.sweep.add_row({r.torque, double(index), r.phi1 * deg, double(point_code(name)), r.ste * 1e6,
                     r.rotation * 1e6, r.normal_force, r.k_secant, r.k_tangent, width(r.k_secant),
                     width(r.k_tangent), double(r.n_pairs), share, r.torque_contact, r.torque_reaction,
                     r.torque_gear / (r.torque * z_ratio), r.p_max / 1e6, r.p_max_edge / 1e6,
                     r.max_root_stress_pinion / 1e6, r.max_root_stress_gear / 1e6, double(s.n_active),
                     double(s.geometry_iterations), double(s.active_set_iterations), double(s.load_cuts),
                     s.complementarity, s.max_penetration * 1e6, r.friction_force, r.power_loss,
                     r.normal_power, state.t_contact + r.t_post});
    for (const auto &p : r.pairs)
      {
        t.pairs.add_row({r.torque, double(index), r.phi1 * deg, double(p.pinion_tooth), double(p.gear_tooth),
                         p.force, p.share, double(p.active_nodes), p.p_max / 1e6, p.p_hertz / 1e6,
                         p.half_width * 1e3, p.a_hertz * 1e3, double(p.resolved), double(p.edge),
                         double(p.slave_body), p.radius_pinion * 1e3, p.root_stress_pinion / 1e6,
                         p.root_radius_pinion * 1e3, p.root_stress_gear / 1e6, p.root_radius_gear * 1e3,
                         p.friction, p.power_loss});
        for (const auto &q : p.profile)
          t.pressure.add_row({r.torque, double(index), r.phi1 * deg, double(p.pinion_tooth), q[0] * 1e3,
                              q[1] * 1e3, q[2] / 1e6});
      }
  }

  std::map<double, int> count_unresolved(const io::SolveResults &t, double min_share)
  {
    std::map<double, int> out;
    const auto T = t.pairs.column("torque"), share = t.pairs.column("load share"),
               res = t.pairs.column("resolved"), edge = t.pairs.column("edge contact");
    for (std::size_t i = 0; i < T.size(); ++i)
      out[T[i]] += share[i] > min_share && res[i] == 0 && edge[i] == 0;
    return out;
  }

  io::SolveResults start_results(const solve::GearContactInput &in, const std::string &input_name,
                                 const std::string &program)
  {
    const auto &pair = in.meshing();
    io::SolveResults t = io::make_solve_results();
    t.attributes       = {{"program", program},
                          {"geometry_hash", in.internal_pair ? geometry::geometry_fingerprint(*in.internal_pair) :
                                                               geometry::geometry_fingerprint(*in.pair)},
                          {"method", contact::to_string(in.contact.method)},
                          {"input", input_name}};
    for (const char *n : {"A", "B", "C", "D", "E"})
      t.line_of_action.add_row({double(point_code(n)), pair.point(n).roll_angle / units::deg});
    return t;
  }

  loading::SweepPlan solve_plan(const GearContactInput &in)
  {
    loading::SweepPlan plan;
    plan.positions = in.positions();
    plan.torques   = in.solve.torques;
    plan.friction  = in.friction_coefficients(plan.torques);
    return plan;
  }

  namespace
  {
    /// The journal of a run: resumed into the tables (and the VTU records), or started afresh.
    loading::SweepStart start_journal(const SolveRunOptions &options, const std::filesystem::path &journal,
                                      const io::JournalHeader &header, io::SolveResults &t, VtuObserver &vtu,
                                      const loading::SweepPlan &plan)
    {
      loading::SweepStart start;
      if (options.resume && std::filesystem::exists(journal))
        start = resume_from(journal, header, t, vtu, plan.positions, plan.torques);
      else
        {
          if (options.out && std::filesystem::exists(journal))
            *options.out << "note: " << journal.string() << " holds an interrupted run; starting afresh "
                         << "(--resume continues it)" << std::endl;
          io::start_journal(journal, header);
        }
      if (options.out && start.next > 0)
        *options.out << "resuming: " << start.next << " of " << plan.size() << " positions from "
                     << journal.string() << std::endl;
      return start;
    }
  } // namespace

  SolveRunResult run_points(post::PointSolver &solver, const GearContactInput &in, const loading::SweepPlan &plan,
                            const SolveRunOptions &options, const PointsSettings &settings)
  {
    validate(options.post);
    SolveRunResult run;
    io::SolveResults &t = run.results;
    t                   = start_results(in, options.input_name, settings.program);
    if (in.contact.friction > 0 || in.friction.law != analytical::friction::Law::constant)
      {
        std::ostringstream mu;
        for (std::size_t i = 0; i < plan.friction.size(); ++i)
          mu << (i ? ", " : "") << std::setprecision(17) << plan.friction[i];
        t.attributes["friction_law"]          = analytical::friction::to_string(in.friction.law);
        t.attributes["friction_coefficients"] = mu.str(); // per torque, in the order of Solve/Torques
        run.friction = plan.friction;
      }
    const bool tables  = settings.tables;
    const bool write   = tables && !options.output_dir.empty(); // no folder: the tables in memory only
    const bool journal = write && settings.journal;
    TablesObserver table_rows(t, in.meshing().ratio(), std::min(in.material[0].thickness, in.material[1].thickness));
    VtuObserver vtu(solver, in.solve, named_vtu_positions(in, plan.positions), options.output_dir);
    const auto journal_path = options.output_dir / journal_file;
    const io::JournalHeader header{"solve", options.input_hash, plan.size()};
    const loading::SweepStart start =
      journal ? start_journal(options, journal_path, header, t, vtu, plan) : loading::SweepStart();
    run.resumed = start.next;

    JournalObserver journal_observer(journal_path, table_rows, vtu);
    ProgressObserver progress(options.out, plan.size(), start.next, settings.progress_every);
    TorqueDoneObserver torque_done(options, t, solver, plan.positions.size());
    std::vector<PositionObserver *> observers;
    if (tables)
      observers.push_back(&table_rows);
    if (write && solver.has_fields())
      observers.push_back(&vtu);
    if (journal)
      observers.push_back(&journal_observer);
    observers.push_back(&progress);
    observers.push_back(&torque_done);
    observers.insert(observers.end(), settings.observers.begin(), settings.observers.end());
    dealii::TimerOutput output_timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    EvaluatingObserver evaluate(solver, output_timer, observers);
    const auto outcome = loading::run_sweep(solver, plan, {&evaluate}, start);
    run.solved       = outcome.finished;
    run.stopped      = outcome.stopped;
    run.pinion_speed = in.friction.pinion_speed;
    run.failure      = outcome.failure;
    if (tables)
      run.unresolved = count_unresolved(t, options.post.unresolved_share);
    if (write)
      {
        dealii::TimerOutput::Scope scope(output_timer, "output");
        io::write_solve_results(t, options.output_dir);
        for (const auto &[T, records] : vtu.pvd)
          if (!records.empty())
            {
              std::ostringstream n;
              n << "pair_T" << T << ".pvd";
              fem::write_pvd(options.output_dir / n.str(), records);
            }
        if (journal && run.failure.empty())
          std::filesystem::remove(journal_path); // complete or stopped by the caller: nothing to resume
      }
    run.seconds = {{"contact", solver.seconds("contact")},
                   {"post", solver.seconds("post")},
                   {"output", contact::section_seconds(output_timer, "output")}};
    return run;
  }

  SolveRunResult run_solve(contact::GearContactModel &model, const solve::GearContactInput &in,
                           const SolveRunOptions &options)
  {
    validate(options.post);
    post::PostOptions post_options = options.post;
    post_options.pinion_speed      = in.friction.pinion_speed;
    // Root stresses and reactions from influence coefficients (fields only for VTU).
    model.observe_root_stress();
    const loading::SweepPlan plan = solve_plan(in);
    post::FeSolver solver(model, post_options, plan.friction);
    return run_points(solver, in, plan, options);
  }

  std::string friction_table(const SolveRunResult &run, const geometry::MeshingPair &pair,
                             const std::vector<double> &torques)
  {
    const auto &sw   = run.results.sweep;
    const auto T_col = sw.column("torque"), loss = sw.column("power loss"), ratio = sw.column("T2 z1/(T1 z2)"),
               T1 = sw.column("T1 contact moment"), fr = sw.column("friction force");
    double any = 0;
    for (const double v : loss)
      any = std::max(any, v);
    if (!(any > 0))
      return "";
    std::ostringstream out;
    out << "\n| T1 [N m] | mu [-] | mean friction force [N] | mean mesh power loss [W] | efficiency from the loss | "
           "efficiency from the torques | mu* [-]: P_loss = P_in mu* H_V (Ohlendorf) |\n|---|---|---|---|---|---|---|\n";
    // Ohlendorf's H_V is stated for external pairs.
    const auto *external = dynamic_cast<const geometry::GearPair *>(&pair);
    const double hv      = external ? analytical::friction::ohlendorf_hv(*external) : 0.0;
    for (std::size_t ti = 0; ti < torques.size(); ++ti)
      {
        const double T = torques[ti];
        // Cycle means: P_in = T1 w1, P_out = T2 w2 = ratio T1 w1 (the ratio column is T2 z1/(T1 z2)).
        double p_loss = 0, p_in = 0, p_out = 0, f = 0;
        int n = 0;
        for (std::size_t i = 0; i < T_col.size(); ++i)
          if (T_col[i] == T)
            p_loss += loss[i], p_in += T1[i], p_out += ratio[i] * T1[i], f += fr[i], ++n;
        if (n == 0 || !(p_in > 0))
          continue;
        const double w1 = run.pinion_speed;
        const double eta_loss = 1.0 - p_loss / (p_in * w1), eta_torque = p_out / p_in;
        out << std::setprecision(5) << "| " << T << " | " << (ti < run.friction.size() ? run.friction[ti] : 0.0)
            << " | " << f / n << " | " << p_loss / n << " | " << eta_loss << " | "
            << eta_torque << " | ";
        if (hv > 0)
          out << (1.0 - eta_loss) / hv << " |\n";
        else
          out << "n/a (internal pair) |\n";
      }
    return out.str();
  }

  std::string summary_table(const SolveRunResult &run, const geometry::MeshingPair &meshing,
                            const std::vector<double> &torques)
  {
    // ISO 6336-1 c_gamma_alpha b for comparison (external pairs; 0: not given).
    double c_gamma = 0;
    if (const auto *external = dynamic_cast<const geometry::GearPair *>(&meshing))
      {
        const auto &pair = *external;
        analytical::iso6336::StiffnessInput si;
        si.z1 = pair.gear(1).teeth(), si.z2 = pair.gear(2).teeth();
        si.x1 = pair.gear(1).parameters().profile_shift, si.x2 = pair.gear(2).parameters().profile_shift;
        si.alpha_n   = pair.gear(1).parameters().rack.pressure_angle;
        si.module    = pair.gear(1).parameters().rack.module;
        si.h_fP1     = pair.gear(1).parameters().rack.dedendum;
        si.h_fP2     = pair.gear(2).parameters().rack.dedendum;
        si.eps_alpha = pair.contact_ratio();
        try
          {
            c_gamma = analytical::iso6336::mesh_stiffness(si).c_gamma_alpha;
          }
        catch (const InputError &)
          {}
      }
    std::ostringstream out;
    out << "| T1 [N m] | mean STE [um] | STE p-p [um] | mean k_secant [N/(mm um)] | ISO 6336-1 "
           "c_gamma_alpha [N/(mm um)] | ratio | max p [MPa] | max root stress pinion/gear [MPa] | "
           "unresolved pair-positions (pairs x positions) |\n|---|---|---|---|---|---|---|---|---|\n";
    const auto &sw = run.results.sweep;
    const auto T_col = sw.column("torque"), ste = sw.column("STE"), k = sw.column("k_secant per width"),
               p = sw.column("p_max"), sp1 = sw.column("root stress pinion"), sp2 = sw.column("root stress gear");
    for (const double T : torques)
      {
        double sum = 0, lo = 1e300, hi = -1e300, ks = 0, pm = 0, s1 = 0, s2 = 0;
        int n = 0;
        for (std::size_t i = 0; i < T_col.size(); ++i)
          if (T_col[i] == T)
            {
              sum += ste[i], ks += k[i], ++n;
              lo = std::min(lo, ste[i]), hi = std::max(hi, ste[i]);
              pm = std::max(pm, p[i]), s1 = std::max(s1, sp1[i]), s2 = std::max(s2, sp2[i]);
            }
        if (n == 0)
          continue;
        const auto u = run.unresolved.find(T);
        out << std::setprecision(4) << "| " << T << " | " << sum / n << " | " << hi - lo << " | " << ks / n << " | ";
        if (c_gamma > 0)
          out << c_gamma << " | " << ks / n / c_gamma;
        else
          out << "n/a | n/a"; // ISO 6336-1 c_gamma_alpha is stated for external pairs
        out << " | " << pm << " | " << s1 << " / "
            << s2 << " | " << (u == run.unresolved.end() ? 0 : u->second) << " |\n";
      }
    out << friction_table(run, meshing, torques);
    return out.str();
  }
} // namespace gearfem::solve
