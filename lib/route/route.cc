// The route of a solve (route/route.h): the choice, the full FE and the stored-cycle routes,
// and the run record's members.
#include "route/route.h"

#include "base/errors.h"
#include "base/memory.h"
#include "base/units.h"
#include "condensed/resolve.h"
#include "model_choice/target.h"
#include "route/detail.h"
#include "solve/error_estimate.h"

#include <iomanip>
#include <sstream>

namespace gearfem::route
{
  std::string to_string(Route r)
  {
    switch (r)
      {
        case Route::full_fe: return "full FE";
        case Route::condensed_cycle: return "condensed cycle";
        case Route::target: return "Solve/Target";
        case Route::hunting_cycle: return "hunting cycle on a condensed cycle";
        case Route::deviations_in_geometry: return "full FE, pitch deviations in the geometry";
      }
    return "?";
  }

  std::pair<Route, std::string> choose(const Request &r)
  {
    const solve::GearContactInput &in   = r.input;
    const bool given                    = r.cycle || !r.cycle_file.empty();
    const model_choice::AccuracyTarget t = model_choice::parse_target(in.solve.target);
    if (r.dev.active())
      {
        if (t.active())
          throw InputError("Solve/Target", in.solve.target, "none with a Deviations section (its cycle has its own mesh)");
        in.require_external("Deviations");
        if (r.dev.model == deviations::DeviationParameters::Model::geometry)
          {
            if (given)
              throw InputError("--condensed", r.cycle_file.empty() ? "(a cycle in memory)" : r.cycle_file.string(),
                               "none with Deviations/Model = geometry",
                               "the deviations are built into the mesh: the full FE is solved, no condensed cycle");
            return {Route::deviations_in_geometry,
                    "Deviations/Model = geometry: the teeth are meshed turned by their pitch deviations"};
          }
        return {Route::hunting_cycle, given ? "Deviations on the given condensed cycle" :
                                              "Deviations: the hunting cycle on a condensed cycle built for the "
                                              "input's torques"};
      }
    if (t.active())
      {
        in.require_external("Solve/Target");
        if (given)
          throw InputError("Solve/Target", in.solve.target, "none with --condensed (a stored cycle has its own mesh)");
        return {Route::target, "Solve/Target = " + in.solve.target + ": the model is chosen and proved on the run"};
      }
    if (given)
      {
        in.require_external("--condensed");
        return {Route::condensed_cycle, "a condensed cycle was given"};
      }
    if (in.solve.error_estimate)
      in.require_external("Solve/Error estimate");
    return {Route::full_fe, "a mesh is given and no Target, Deviations or condensed cycle"};
  }

  namespace detail
  {
    void set_member(std::vector<std::pair<std::string, std::string>> &record, const std::string &name,
                    const std::string &json)
    {
      for (auto &[n, v] : record)
        if (n == name)
          {
            v = json;
            return;
          }
      record.emplace_back(name, json);
    }

    std::string json_string(const std::string &s)
    {
      std::string q = "\"";
      for (const char c : s)
        {
          if (c == '"' || c == '\\')
            q += '\\';
          if (c == '\n')
            {
              q += "\\n";
              continue;
            }
          q += c;
        }
      return q + "\"";
    }

    solve::SolveRunOptions run_options(const Request &r)
    {
      solve::SolveRunOptions opt;
      opt.output_dir = r.output_dir;
      opt.input_name = r.input_name;
      opt.input_hash = r.input_hash;
      opt.resume     = r.resume;
      opt.out        = r.out;
      opt.post       = r.post;
      return opt;
    }

    solve::SolveRunResult full_fe_sweep(contact::GearContactModel &model, const Request &r, Outcome &o,
                                        const FullFeCost &cost,
                                        const std::function<bool(std::size_t, const Table &, double)> &torque_done)
    {
      const solve::GearContactInput &in = r.input;
      std::ostream *out                 = r.out;
      for (int i = 1; i <= 2; ++i)
        if (out && model.body(i).mesh().subdivided)
          *out << "note: gear " << i << "'s all-quad mesh comes from gmsh's subdivision fallback (Blossom "
               << "recombination failed): smaller, less regular cells; `gearfem mesh` reports its quality"
               << std::endl;
      solve::SolveRunOptions opt = run_options(r);
      opt.torque_done            = torque_done;
      solve::SolveRunResult res  = solve::run_solve(model, in, opt);
      if (res.stopped)
        {
          if (out)
            *out << "sweep stopped after " << res.solved
                 << " positions: its p-p STE already asks for a finer level\n";
          return res;
        }
      if (in.solve.plots && res.results.sweep.n_rows() > 0)
        o.plots = {"plot_solve.py"};
      if (!res.failure.empty())
        {
          o.failure = res.failure + "\n  the " + std::to_string(res.results.sweep.n_rows()) +
                      " completed positions are saved in " + r.output_dir.string() +
                      " (their journal stays: with the input unchanged, --resume retries from the failed position)";
          return res;
        }
      if (out)
        *out << "\n" << solve::summary_table(res, in.meshing(), in.solve.torques) << "time: contact "
             << res.seconds.at("contact") << " s, post-processing " << res.seconds.at("post") << " s, output "
             << res.seconds.at("output") << " s" << (cost.label.empty() ? "" : " (" + cost.label + ")") << "\n";
      // The cost of the run, for the speed-against-error study (validation/speed_vs_error).
      std::ostringstream c;
      c << std::setprecision(6) << "{" << (cost.label.empty() ? "" : "\"deviations_in_geometry\": true, ")
        << "\"dofs\": " << model.n_dofs() << ", \"mesh_seconds\": " << cost.mesh_seconds
        << ", \"setup_seconds\": " << cost.setup_seconds << ", \"contact_seconds\": " << res.seconds.at("contact")
        << ", \"post_seconds\": " << res.seconds.at("post") << ", \"output_seconds\": " << res.seconds.at("output")
        << ", \"positions\": " << res.results.sweep.n_rows() << ", \"peak_memory_mb\": " << peak_memory_mb()
        << ", \"cpu_setup_seconds\": " << cost.cpu_setup
        << ", \"cpu_sweep_seconds\": " << process_cpu_seconds() - cost.cpu_setup << "}";
      set_member(o.record, "cost", c.str());
      if (!res.friction.empty())
        {
          // The coefficient applied at each torque, at full precision (docs/friction.md).
          std::ostringstream f;
          f << std::setprecision(17) << "{\"law\": \"" << analytical::friction::to_string(in.friction.law)
            << "\", \"pinion_speed_rpm\": " << in.friction.pinion_speed * 30 / units::pi << ", \"torques\": [";
          for (std::size_t i = 0; i < in.solve.torques.size(); ++i)
            f << (i ? ", " : "") << in.solve.torques[i];
          f << "], \"coefficients\": [";
          for (std::size_t i = 0; i < res.friction.size(); ++i)
            f << (i ? ", " : "") << res.friction[i];
          f << "]}";
          set_member(o.record, "friction", f.str());
        }
      return res;
    }

    solve::SolveRunResult report_condensed(solve::SolveRunResult res, const Request &r, Outcome &o, double cpu_setup,
                                           unsigned int dofs, double build_seconds)
    {
      const solve::GearContactInput &in = r.input;
      if (in.solve.plots && res.results.sweep.n_rows() > 0)
        o.plots = {"plot_solve.py"};
      if (!res.failure.empty())
        {
          o.failure = res.failure + "\n  the " + std::to_string(res.results.sweep.n_rows()) +
                      " completed positions are saved in " + r.output_dir.string();
          return res;
        }
      if (r.out)
        *r.out << "\n" << solve::summary_table(res, in.meshing(), in.solve.torques) << "time: contact "
               << res.seconds.at("contact") << " s, post-processing " << res.seconds.at("post") << " s, output "
               << res.seconds.at("output") << " s (" << res.results.sweep.n_rows()
               << " positions on the condensed cycle)\n";
      std::ostringstream cost;
      cost << std::setprecision(6) << "{\"condensed\": true, \"build_seconds\": " << build_seconds
           << ", \"contact_seconds\": " << res.seconds.at("contact") << ", \"post_seconds\": " << res.seconds.at("post")
           << ", \"output_seconds\": " << res.seconds.at("output") << ", \"positions\": " << res.results.sweep.n_rows()
           << ", \"dofs\": " << dofs << ", \"peak_memory_mb\": " << peak_memory_mb()
           << ", \"cpu_setup_seconds\": " << cpu_setup
           << ", \"cpu_sweep_seconds\": " << process_cpu_seconds() - cpu_setup << "}";
      set_member(o.record, "cost", cost.str());
      return res;
    }
  } // namespace detail

  namespace
  {
    void print_header(const Request &r)
    {
      if (!r.out)
        return;
      const solve::GearContactInput &in = r.input;
      const auto &pair                  = in.meshing();
      std::ostream &out                 = *r.out;
      out << "solve: z " << pair.teeth(1) << "/" << pair.teeth(2) << (pair.is_internal() ? " (internal)" : "") << ", a "
          << pair.center_distance() * 1e3 << " mm, contact ratio " << pair.contact_ratio() << ", "
          << in.positions().size() << " positions x " << in.solve.torques.size() << " torques, method "
          << contact::to_string(in.contact.method) << ", slave body " << in.contact.slave << ", "
          << (in.material[0].model == fem::PlaneModel::plane_stress ? "plane stress" : "plane strain") << "\n";
      for (const auto &w : solve::input_warnings(in))
        out << "warning: " << w << "\n";
    }

    /// A given cycle: the one in memory, else the file's (read into `storage`).
    const condensed::CondensedCycle &given_cycle(const Request &r, condensed::CondensedCycle &storage)
    {
      if (r.cycle)
        return *r.cycle;
      storage = condensed::read_cycle(r.cycle_file, r.input.solve.torques); // the scenes of its torques
      return storage;
    }

    void run_on_cycle(const Request &r, Outcome &o)
    {
      condensed::CondensedCycle storage;
      const condensed::CondensedCycle &cycle = given_cycle(r, storage);
      const condensed::Resolver check(cycle, r.input); // refuses a different model or position
      if (r.out)
        *r.out << "condensed cycle: " << (r.cycle ? std::string("in memory") : r.cycle_file.string()) << ", "
               << cycle.positions.size() << " positions built at " << cycle.build_torque << " N m (" << cycle.dofs
               << " DoFs)\n";
      if (r.validate_only)
        return;
      const double cpu_setup = process_cpu_seconds(); // parsing and reading the cycle
      o.run = detail::report_condensed(condensed::run_condensed(cycle, r.input, detail::run_options(r)), r, o,
                                       cpu_setup, cycle.dofs, 0);
    }

    void error_estimate(contact::GearContactModel &model, const Request &r, Outcome &o)
    {
      const solve::GearContactInput &in = r.input;
      solve::ErrorEstimateOptions eo;
      eo.post = r.post;
      eo.out  = r.out;
      if (r.out)
        *r.out << "\nerror estimate: " << solve::error_sample_positions(*in.pair).size() << " sample positions x "
               << in.solve.torques.size() << " torques on two mesh levels (Solve/Error estimate)" << std::endl;
      const solve::ErrorEstimate e = solve::estimate_error(model, in, eo);
      const double sweep = o.run.seconds.at("contact") + o.run.seconds.at("post") + o.run.seconds.at("output");
      if (r.out)
        *r.out << "\n" << solve::error_estimate_table(e) << "cost of the estimate " << e.seconds()
               << " s against the run's set-up " << model.setup_seconds() << " s + sweep " << sweep << " s\n";
      detail::set_member(o.record, "error_estimate",
                         solve::error_estimate_json(e, {{"run_setup_seconds", model.setup_seconds()},
                                                        {"run_sweep_seconds", sweep}}));
    }

    void run_full_fe(const Request &r, Outcome &o)
    {
      if (r.validate_only)
        return;
      const solve::GearContactInput &in = r.input;
      auto model                        = in.model();
      const double cpu_setup            = process_cpu_seconds(); // parsing, meshing, assembly, factorisation
      if (r.out)
        *r.out << "model: " << model->n_dofs() << " DoFs (" << model->body(1).n_dofs() << " + "
               << model->body(2).n_dofs() << "), " << model->body(1).triangulation().n_active_cells() << " + "
               << model->body(2).triangulation().n_active_cells() << " cells, mesh " << std::setprecision(3)
               << model->mesh_seconds() << " s, set-up (mesh, assemble, factorise) " << model->setup_seconds()
               << " s" << std::endl;
      o.run = detail::full_fe_sweep(*model, r, o, {model->setup_seconds(), cpu_setup, model->mesh_seconds(), ""}, {});
      if (!o.failure.empty())
        return;
      if (in.solve.error_estimate)
        error_estimate(*model, r, o);
      int n_unresolved = 0;
      for (const auto &[T, n] : o.run.unresolved)
        n_unresolved += n;
      if (n_unresolved > 0 && r.out)
        *r.out << "warning: " << n_unresolved
               << " loaded tooth-pair positions (each loaded pair at each position, all torques) have fewer than "
               << r.post.min_patch_nodes
               << " contact nodes across the patch (Post/Min patch nodes): their peak pressure is unresolved "
                  "(refine Mesh/h_contact; column \"resolved\" of pairs.csv); STE, stiffness and root stress are "
                  "not affected\n";
    }
  } // namespace

  Outcome run(Request &r)
  {
    print_header(r);
    Outcome o;
    std::tie(o.route, o.why) = choose(r);
    switch (o.route)
      {
        case Route::full_fe: run_full_fe(r, o); break;
        case Route::condensed_cycle: run_on_cycle(r, o); break;
        case Route::target: detail::run_target(r, o); break;
        case Route::hunting_cycle: detail::run_hunting(r, o); break;
        case Route::deviations_in_geometry: detail::run_geometry(r, o); break;
      }
    if (r.validate_only)
      o.plots.clear();
    detail::set_member(o.record, "route",
                       "{\"name\": " + detail::json_string(to_string(o.route)) + ", \"why\": " +
                         detail::json_string(o.why) + "}");
    return o;
  }
} // namespace gearfem::route
