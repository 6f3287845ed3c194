// The Python module's calls beside the solve (python/module.cc): pair kinematics and tooth
// profiles, the deviation draws of a tolerance grade, ISO 6336 / AGMA ratings, helical slicing
// and a dynamics run. Each is the library's call that the matching command makes.
#include "python/input.h"
#include "python/results.h"

#include "base/errors.h"
#include "base/units.h"
#include "deviations/parameters.h"
#include "dynamics/case.h"
#include "dynamics/law_factory.h"
#include "dynamics/parameters.h"
#include "dynamics/report.h"
#include "helical/run.h"
#include "system_deflection/run.h"
#include "system_deflection/train.h"
#include "commands/helical_input.h"
#include "rating/parameters.h"
#include "rating/rating.h"
#include "route/route.h"

#include <deal.II/base/parameter_handler.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace gearfem::python
{
  namespace
  {
    py::array_t<double> array(const std::vector<double> &v)
    {
      py::array_t<double> a(py::ssize_t(v.size()));
      std::copy(v.begin(), v.end(), a.mutable_data());
      return a;
    }

    solve::GearContactInput solve_input(const Input &in)
    {
      dealii::ParameterHandler prm;
      route::declare_request(prm);
      parse(in, prm);
      return solve::parse_gear_contact_input(prm);
    }

    /// Pair kinematics and both gears' sampled outlines (mm, as profile_gear<i>.csv).
    py::dict pair(const Input &in, double spacing_mm)
    {
      const solve::GearContactInput s = solve_input(in);
      const auto &p                   = s.meshing();
      py::dict d;
      d["teeth"]                   = std::make_pair(p.teeth(1), p.teeth(2));
      d["centre distance [mm]"]    = p.center_distance() / units::mm;
      d["working pressure angle [deg]"] = p.working_pressure_angle() / units::deg;
      d["contact ratio"]           = p.contact_ratio();
      d["base pitch [mm]"]         = p.base_pitch() / units::mm;
      d["internal"]                = p.is_internal();
      py::dict points;
      for (const char *n : {"A", "B", "C", "D", "E"})
        points[n] = p.point(n).roll_angle / units::deg;
      d["roll angle [deg]"] = points;
      if (s.pair)
        for (int g = 1; g <= 2; ++g)
          {
            std::vector<double> x, y, k;
            for (const auto &q : s.pair->gear(g).sample(spacing_mm * units::mm))
              x.push_back(q.p.x() / units::mm), y.push_back(q.p.y() / units::mm), k.push_back(q.curvature * units::mm);
            py::dict o;
            o["x [mm]"]             = array(x);
            o["y [mm]"]             = array(y);
            o["curvature [1/mm]"]   = array(k);
            d[("gear " + std::to_string(g)).c_str()] = o;
          }
      return d;
    }

    /// The deviations of both gears: the given ones or draw `sample` of the grade.
    py::dict deviation_draws(const Input &in, long sample)
    {
      dealii::ParameterHandler prm;
      route::declare_request(prm);
      parse(in, prm);
      const solve::GearContactInput s           = solve::parse_gear_contact_input(prm);
      const deviations::DeviationParameters dev = deviations::parse_deviation_parameters(prm);
      const geometry::PairDeviations d          = deviations::resolve_deviations(dev, *s.pair, std::uint64_t(sample));
      py::dict out;
      for (int b = 0; b < 2; ++b)
        {
          const auto &g = d.gear[b];
          std::vector<double> fpt, Fp, fha;
          for (const double v : g.f_pt)
            fpt.push_back(v / units::um);
          for (const double v : g.cumulative_pitch())
            Fp.push_back(v / units::um);
          for (const double v : g.f_Ha)
            fha.push_back(v / units::um);
          py::dict o;
          o["f_pt [um]"]           = array(fpt);
          o["F_p [um]"]            = array(Fp);
          o["f_Ha [um]"]           = array(fha);
          o["F_r [um]"]            = 2 * g.eccentricity / units::um;
          o["runout phase [deg]"]  = g.eccentricity_phase / units::deg;
          out[("gear " + std::to_string(b + 1)).c_str()] = o;
        }
      return out;
    }

    /// ISO 6336 and AGMA ratings: {"standard/symbol": values per torque}, with "torques".
    py::dict rate(const Input &in)
    {
      dealii::ParameterHandler prm;
      route::declare_request(prm);
      rating::declare_rating_parameters(prm);
      parse(in, prm);
      const solve::GearContactInput s = solve::parse_gear_contact_input(prm);
      if (!s.pair)
        throw InputError("Pair/Type", "internal", "external (gearfem.rate; `gearfem rate` rates internal pairs)");
      const rating::RatingReport r = rating::rate(*s.pair, rating::parse_rating_parameters(prm));
      py::dict out;
      out["torques [N m]"] = array(r.torques);
      for (const auto &row : r.rows)
        out[(row.standard + "/" + row.symbol + (row.unit.empty() ? "" : " [" + row.unit + "]")).c_str()] =
          array(row.values);
      return out;
    }

    /// The helical pair of the input (Helical section; on its shafts with System/Coupling =
    /// shafts): per torque the summary of `gearfem helical`.
    py::list helical_run(const Input &in, const py::object &progress)
    {
      dealii::ParameterHandler prm;
      helical::declare_request(prm);
      system_deflection::declare_system_parameters(prm);
      parse(in, prm);
      helical::Request req = helical::parse_request(prm);
      const system_deflection::SystemInput sys = system_deflection::parse_system_parameters(prm);
      const solve::GearContactInput &s = req.section;
      const helical::SlicingOptions &o = req.slicing;
      helical::RunOptions &ro          = req.run;
      ProgressStream stream(progress);
      ro.out = stream.get();
      system_deflection::CoupledRun job;
      {
        py::gil_scoped_release release;
        job = system_deflection::run_job(s, o, ro, sys);
      }
      const helical::HelicalRun &r = job.helical;
      if (!r.failure.empty())
        throw SolverError(r.failure);
      py::list out;
      for (std::size_t i = 0; i < r.summary.size(); ++i)
        {
          const auto &t = r.summary[i];
          py::dict d;
          d["torque [N m]"]              = t.torque;
          d["STE mean [um]"]             = t.ste_mean / units::um;
          d["STE p-p [um]"]              = t.ste_pp / units::um;
          d["mesh stiffness [N/um]"]     = t.k_mean * units::um;
          d["c_gamma [N/(mm um)]"]       = t.c_gamma_iso();
          d["K_Hbeta"]                   = t.k_h_beta;
          d["p_max [MPa]"]               = t.p_max / 1e6;
          d["root stress pinion [MPa]"]  = t.root_stress_pinion / 1e6;
          d["root stress gear [MPa]"]    = t.root_stress_gear / 1e6;
          if (sys.coupled && i < job.iso.size())
            {
              // On the shafts: ISO 6336-1 method C beside, and the lead correction when designed.
              d["F_beta_y [um]"]           = job.iso[i].f_beta_y / units::um;
              d["K_Hbeta ISO method C"]    = job.iso[i].k_h_beta;
              if (job.corrected)
                {
                  d["correction slope [um]"]    = job.design.correction.slope / units::um;
                  d["correction crowning [um]"] = job.design.correction.crowning / units::um;
                }
            }
          out.append(d);
        }
      return out;
    }

    /// `gearfem system` of the input (a Train section; its stages' files relative to the input's
    /// folder): per stage the summary per torque, the ratios, and the bearings' reactions.
    py::dict system_run(const Input &in, const py::object &progress)
    {
      dealii::ParameterHandler prm;
      system_deflection::declare_train_parameters(prm);
      parse(in, prm);
      auto train = system_deflection::parse_train_parameters(prm, std::filesystem::path(in.dir) / in.name);
      for (auto &st : train.stages)
        st.request = commands::read_helical_input(st.input);
      ProgressStream stream(progress);
      system_deflection::TrainRun run;
      {
        py::gil_scoped_release release;
        run = system_deflection::run_train(std::move(train), stream.get());
      }
      if (!run.failure.empty())
        throw SolverError(run.failure);
      py::list stages;
      for (std::size_t k = 0; k < run.stages.size(); ++k)
        {
          py::list rows;
          for (std::size_t i = 0; i < run.stages[k].summary.size(); ++i)
            {
              const auto &t = run.stages[k].summary[i];
              py::dict d;
              d["torque [N m]"]         = t.torque;
              d["STE mean [um]"]        = t.ste_mean / units::um;
              d["STE p-p [um]"]         = t.ste_pp / units::um;
              d["K_Hbeta"]              = t.k_h_beta;
              d["p_max [MPa]"]          = t.p_max / 1e6;
              d["root stress pinion [MPa]"] = t.root_stress_pinion / 1e6;
              d["root stress gear [MPa]"]   = t.root_stress_gear / 1e6;
              if (i < run.iso[k].size())
                d["F_beta_y [um]"] = run.iso[k][i].f_beta_y / units::um,
                d["K_Hbeta ISO method C"] = run.iso[k][i].k_h_beta;
              rows.append(d);
            }
          stages.append(rows);
        }
      std::vector<double> T, Fx, Fy, Fz, shaft;
      py::list names;
      for (const auto &ts : run.shafts)
        for (std::size_t i = 0; i < ts.solution.reactions.size(); ++i)
          {
            const auto &r = ts.solution.reactions[i];
            T.push_back(ts.torque), shaft.push_back(run.system.bearings[i].shaft);
            Fx.push_back(r.force.x()), Fy.push_back(r.force.y()), Fz.push_back(r.force.z());
            names.append(r.name);
          }
      py::dict bearings;
      bearings["torque [N m]"] = array(T), bearings["shaft"] = array(shaft), bearings["bearing"] = names;
      bearings["F_x [N]"] = array(Fx), bearings["F_y [N]"] = array(Fy), bearings["F_z [N]"] = array(Fz);
      py::dict out;
      out["stages"]   = stages;
      out["ratio"]    = array(run.ratio);
      out["bearings"] = bearings;
      return out;
    }

    /// `gearfem dynamics` of the input (Dynamics sections): its tables as dicts of arrays.
    py::dict dynamics_run(const Input &in, const py::object &progress)
    {
      dealii::ParameterHandler prm;
      dynamics::declare_parameters(prm);
      parse(in, prm);
      dynamics::DynamicsCase c = dynamics::parse_parameters(prm, in.dir);
      std::vector<std::string> notes;
      if (c.law == dynamics::LawKind::external)
        c.external_law = dynamics::external_law(c, c.backlash, notes);
      auto model = dynamics::build_model(c, &notes);
      ProgressStream stream(progress);
      dynamics::CaseReport report;
      {
        py::gil_scoped_release release;
        report = dynamics::run_case(c, *model, stream.get());
      }
      py::dict out;
      for (const auto &[name, table] : report.tables)
        out[name.c_str()] = table_dict(table);
      out["summary"] = report.summary;
      return out;
    }
  } // namespace

  void bind_extras(py::module_ &m)
  {
    m.def("pair", &pair, py::arg("input"), py::arg("spacing_mm") = 0.05,
          "Pair kinematics (centre distance, working pressure angle, contact ratio, points A-E) and both "
          "gears' sampled outlines.");
    m.def("deviation_draws", &deviation_draws, py::arg("input"), py::arg("sample") = 0,
          "The deviations of both gears of the input's Deviations section: given, or draw `sample` of its "
          "ISO 1328-1 grade (the draw of Monte Carlo sample `sample`).");
    m.def("rate", &rate, py::arg("input"), "ISO 6336-2/-3 and AGMA 2101 stresses and factors per torque.");
    m.def("helical", &helical_run, py::arg("input"), py::arg("progress") = py::none(),
          "A helical pair by face-width slicing (the Helical section): the summary per torque.");
    m.def("system", &system_run, py::arg("input"), py::arg("progress") = py::none(),
          "A parallel-axis gear train on its shafts (the Train section, its stages' helical input files): "
          "per stage the summary per torque, the torque ratios and the bearings' reactions.");
    m.def("dynamics", &dynamics_run, py::arg("input"), py::arg("progress") = py::none(),
          "Nonlinear pair dynamics of the input's dynamics sections: its tables (response, sweep, ...).");
  }
} // namespace gearfem::python
