// The Python module `gearfem` (docs/python.md): the library's one entry point (route::run) and
// the condensed cycle, numpy in and out. Input errors raise gearfem.InputError (a ValueError),
// solver failures gearfem.SolverError (a RuntimeError); long calls release the GIL and report
// progress to an optional callable, one line at a time; nothing is printed by default.
#include "python/input.h"
#include "python/results.h"

#include "base/errors.h"
#include "base/number.h"
#include "commands/command.h"
#include "condensed/condense.h"
#include "io/journal.h"
#include "route/route.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <pybind11/stl.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

namespace py = pybind11;

namespace gearfem::python
{
  namespace
  {
    /// Parses `in` as a solve request (InputError naming the entry).
    void check(const Input &in)
    {
      dealii::ParameterHandler prm;
      route::declare_request(prm);
      parse(in, prm);
      (void)route::parse_request(prm);
    }

    Input read_input(const std::string &file, const std::map<std::string, py::object> &set)
    {
      if (!std::filesystem::is_regular_file(file))
        throw InputError("input file", file, "an existing readable file", "file not found");
      std::ostringstream text;
      text << std::ifstream(file).rdbuf();
      Input in{text.str(), std::filesystem::path(file).filename().string(),
               std::filesystem::path(file).parent_path().string()};
      std::map<std::string, std::string> entries;
      for (const auto &[k, v] : set)
        entries[k] = prm_value(v);
      in = in.with(entries);
      check(in); // bad input fails here, not at the first solve
      return in;
    }

    Input from_dict(const py::dict &sections, const std::string &name)
    {
      Input in{sections_text(sections), name};
      check(in);
      return in;
    }

    /// The request of `in`: parsed and checked, its output folder created (empty: in memory).
    route::Request request(const Input &in, const std::string &output_dir)
    {
      dealii::ParameterHandler prm;
      route::declare_request(prm);
      parse(in, prm);
      route::Request r = route::parse_request(prm);
      r.input_name     = in.name;
      r.input_hash     = io::content_hash(in.text);
      if (!output_dir.empty())
        {
          std::filesystem::create_directories(output_dir);
          r.output_dir = output_dir;
        }
      return r;
    }

    /// route::run without the GIL; the plots of the route where asked (needs a folder).
    Results run(route::Request &r, const py::object &progress, bool plots)
    {
      ProgressStream stream(progress);
      r.out = stream.get();
      route::Outcome o;
      {
        py::gil_scoped_release release;
        o = route::run(r);
      }
      if (!o.failure.empty())
        throw SolverError(o.failure);
      if (plots && !r.output_dir.empty())
        for (const auto &script : o.plots)
          commands::run_plot_script(script, {r.output_dir.string()}, nullptr);
      return results_of(o);
    }

    Results solve(const Input &in, const std::string &output_dir, const py::object &progress, bool resume,
                  bool plots)
    {
      route::Request r = request(in, output_dir);
      r.resume         = resume;
      return run(r, progress, plots);
    }

    /// A condensed cycle in memory with the input it was built from (on the gap route, so
    /// that a relief variant is a gap modification of the same model).
    struct Cycle
    {
      std::shared_ptr<const condensed::CondensedCycle> cycle;
      Input input;
      /// The request of `input`, parsed once for the variants that change only the torques
      /// (a parse costs about as much as re-solving a hundred positions); its lock.
      std::shared_ptr<route::Request> base;
      std::shared_ptr<std::mutex> lock = std::make_shared<std::mutex>();

      /// Torques of a variant, checked as Solve/Torques is, and within the cycle's range.
      std::vector<double> torque_list(const py::object &torques) const
      {
        const std::string text = prm_value(torques);
        const std::vector<double> T = parse_double_list("Solve/Torques", text);
        if (T.empty())
          throw InputError("Solve/Torques", "(empty)", "one or more torques > 0 N m");
        for (const double t : T)
          {
            require_greater("Solve/Torques", t, 0.0, "N m");
            if (t < cycle->torque_lo * (1 - 1e-12) || t > cycle->torque_hi * (1 + 1e-12))
              throw InputError("Solve/Torques", to_string_g(t) + " N m",
                               to_string_g(cycle->torque_lo) + " to " + to_string_g(cycle->torque_hi) +
                                 " N m (the torque range of the condensed cycle)",
                               "condense with a Condense/Torque range that holds it");
          }
        return T;
      }

      Results solve(const py::object &torques, const py::dict &relief, const py::dict &deviations,
                    const std::string &output_dir, const py::object &progress)
      {
        if (relief.empty() && deviations.empty())
          {
            // Only the torques change: the parsed request of the cycle's input, re-targeted.
            std::lock_guard<std::mutex> guard(*lock);
            if (!base)
              base = std::make_shared<route::Request>(request(input, ""));
            route::Request &r = *base;
            const std::vector<double> kept = r.input.solve.torques;
            if (!torques.is_none())
              r.input.solve.torques = torque_list(torques);
            r.output_dir = output_dir;
            if (!output_dir.empty())
              std::filesystem::create_directories(output_dir);
            r.cycle = cycle.get();
            try
              {
                Results res = run(r, progress, false);
                r.input.solve.torques = kept;
                return res;
              }
            catch (...)
              {
                r.input.solve.torques = kept;
                throw;
              }
          }
        std::map<std::string, std::string> entries;
        if (!torques.is_none())
          entries["Solve/Torques"] = prm_value(torques);
        for (const auto &[k, v] : relief)
          entries[py::str(k).cast<std::string>()] = prm_value(v);
        for (const auto &[k, v] : deviations)
          {
            const std::string key = py::str(k).cast<std::string>();
            entries[key.rfind("Deviations/", 0) == 0 ? key : "Deviations/" + key] = prm_value(v);
          }
        route::Request r = request(input.with(entries), output_dir);
        r.cycle          = cycle.get();
        return run(r, progress, false);
      }
      void save(const std::string &file) const { condensed::write_cycle(*cycle, file); }
    };

    Input on_gap_route(Input in) { return in.with({{"Contact/Micro-geometry", "gap"}}); }

    Cycle condense(const Input &in, const py::object &progress)
    {
      const Input gap = on_gap_route(in);
      dealii::ParameterHandler prm;
      route::declare_request(prm);
      condensed::declare_condense_parameters(prm);
      parse(gap, prm);
      const solve::GearContactInput input = solve::parse_gear_contact_input(prm);
      const condensed::CondenseParameters cp = condensed::parse_condense_parameters(prm);
      ProgressStream stream(progress);
      auto c = std::make_shared<condensed::CondensedCycle>();
      {
        py::gil_scoped_release release;
        *c = condensed::condense(input, cp, stream.get());
      }
      c->input_name = in.name;
      c->input_text = gap.text;
      return Cycle{c, gap, nullptr};
    }

    Cycle load_cycle(const std::string &file)
    {
      auto c = std::make_shared<condensed::CondensedCycle>(condensed::read_cycle(file));
      if (c->input_text.empty())
        throw InputError("condensed cycle", file, "a cycle that carries its input (attribute input_text)",
                         "it was written before cycles kept their input: build it again with gearfem condense");
      return Cycle{c, Input{c->input_text, c->input_name.empty() ? "input.prm" : c->input_name, ""}, nullptr};
    }
  } // namespace

  void bind_extras(py::module_ &m); // extras.cc
} // namespace gearfem::python

PYBIND11_MODULE(gearfem, m)
{
  using namespace gearfem;
  using namespace gearfem::python;
  m.doc() = "gearfem: finite-element loaded tooth contact analysis of gear pairs (docs/python.md)";
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<SolverError> solver_error(m, "SolverError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try
      {
        if (p)
          std::rethrow_exception(p);
      }
    catch (const InputError &e)
      {
        PyErr_SetString(input_error.ptr(), e.what());
      }
    catch (const SolverError &e)
      {
        PyErr_SetString(solver_error.ptr(), e.what());
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        PyErr_SetString(solver_error.ptr(), s.str().c_str());
      }
  });

  py::class_<Input>(m, "Input", "A solve input: the text of a .prm file, parsed and checked on use.")
    .def_readonly("text", &Input::text)
    .def_readonly("name", &Input::name)
    .def_static("from_dict", &from_dict, py::arg("sections"), py::arg("name") = "input.prm",
                "An input from nested sections, e.g. {'Rack': {'Module': 3}, 'Gear 1': {...}}.")
    .def(
      "set",
      [](const Input &in, const std::map<std::string, py::object> &entries) {
        std::map<std::string, std::string> e;
        for (const auto &[k, v] : entries)
          e[k] = prm_value(v);
        Input out = in.with(e);
        check(out);
        return out;
      },
      py::arg("entries"), "The input with entries {'Solve/Torques': [100, 200], ...} set (checked).")
    .def("get", &Input::get, py::arg("path"), "The value of an entry, e.g. 'Solve/Torques'.")
    .def("__repr__", [](const Input &in) { return "<gearfem.Input " + in.name + ">"; });

  bind_results(m);

  py::class_<Cycle>(m, "Cycle", "A condensed mesh cycle in memory, with the input it was built from.")
    .def("solve", &Cycle::solve, py::arg("torques") = py::none(), py::arg("relief") = py::dict(),
         py::arg("deviations") = py::dict(), py::arg("output_dir") = "", py::arg("progress") = py::none(),
         "Re-solve a variant on the cycle: other torques, tip-relief entries ({'Gear 1/Tip relief amount': 10, "
         "...}), deviations ({'Accuracy grade': 6, 'Seed': 3} or given deviations: the hunting cycle).")
    .def("save", &Cycle::save, py::arg("file"), "Write condensed.h5 (docs/output-format.md).")
    .def_property_readonly("input", [](const Cycle &c) { return c.input; })
    .def_property_readonly("torque_range",
                           [](const Cycle &c) { return std::make_pair(c.cycle->torque_lo, c.cycle->torque_hi); })
    .def_property_readonly("build_torque", [](const Cycle &c) { return c.cycle->build_torque; })
    .def_property_readonly("positions", [](const Cycle &c) { return c.cycle->positions.size(); })
    .def_property_readonly("dofs", [](const Cycle &c) { return c.cycle->dofs; })
    .def_property_readonly("build_seconds", [](const Cycle &c) { return c.cycle->build_seconds; });

  m.def("read_input", &read_input, py::arg("file"), py::arg("set") = std::map<std::string, py::object>(),
        "Read a .prm input (checked as the CLI checks it), with entries {'Solve/Torques': 340} set after it.");
  m.def("solve", &gearfem::python::solve, py::arg("input"), py::arg("output_dir") = "", py::arg("progress") = py::none(),
        py::arg("resume") = false, py::arg("plots") = false,
        "Solve an input on the route `gearfem solve` takes (route::run). Without output_dir the results stay in "
        "memory.");
  m.def("condense", &gearfem::python::condense, py::arg("input"), py::arg("progress") = py::none(),
        "Build the condensed cycle of an input in memory (the Condense section's build torque and range).");
  m.def("load_cycle", &load_cycle, py::arg("file"), "Read a condensed.h5 that carries its input.");
  bind_extras(m);
}
