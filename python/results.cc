// Results of the Python module (python/results.h).
#include "python/results.h"

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace gearfem::python
{
  py::dict table_dict(const Table &t)
  {
    py::dict d;
    const auto headers = t.headers();
    for (std::size_t c = 0; c < t.n_columns(); ++c)
      {
        py::array_t<double> a(py::ssize_t(t.n_rows()));
        auto v = a.mutable_unchecked<1>();
        for (std::size_t i = 0; i < t.n_rows(); ++i)
          v(py::ssize_t(i)) = t.row(i)[c];
        d[py::str(headers[c])] = a;
      }
    return d;
  }

  Results results_of(const route::Outcome &o)
  {
    Results r;
    const io::SolveResults &t = o.run.results;
    r.sweep          = table_dict(t.sweep);
    r.pairs          = table_dict(t.pairs);
    r.pressure       = table_dict(t.pressure);
    r.line_of_action = table_dict(t.line_of_action);
    r.route          = route::to_string(o.route);
    std::string json = "{";
    for (std::size_t k = 0; k < o.record.size(); ++k)
      json += (k ? ", \"" : "\"") + o.record[k].first + "\": " + o.record[k].second;
    json += "}";
    r.run = py::module_::import("json").attr("loads")(json);
    return r;
  }

  void bind_results(py::module_ &m)
  {
    py::class_<Results>(m, "Results",
                        "The tables of a solve as dicts of numpy arrays keyed by the CSV column names "
                        "(docs/output-format.md), and the run record.")
      .def_readonly("sweep", &Results::sweep, "sweep.csv: one row per (torque, position)")
      .def_readonly("pairs", &Results::pairs, "pairs.csv: one row per loaded tooth pair and position")
      .def_readonly("pressure", &Results::pressure, "pressure.csv: one row per contact node")
      .def_readonly("line_of_action", &Results::line_of_action, "line_of_action.csv: the points A..E")
      .def_readonly("run", &Results::run, "run.json's members: route (name, why), cost, model_choice, ...")
      .def_readonly("route", &Results::route)
      .def("__repr__", [](const Results &r) {
        return "<gearfem.Results " + r.route + ", " + std::to_string(py::len(r.sweep) ? py::len(r.sweep.begin()->second) : 0) +
               " sweep rows>";
      });
  }

  ProgressStream::ProgressStream(const py::object &callback)
  {
    if (callback.is_none())
      return;
    buffer_ = std::make_unique<Buffer>(callback);
    stream_ = std::make_unique<std::ostream>(buffer_.get());
  }

  ProgressStream::~ProgressStream() = default;

  ProgressStream::Buffer::~Buffer()
  {
    py::gil_scoped_acquire gil;
    cb_ = py::object();
  }

  int ProgressStream::Buffer::overflow(int c)
  {
    if (c == traits_type::eof())
      return 0;
    if (c != '\n')
      {
        line_ += char(c);
        return c;
      }
    if (!failed_)
      {
        py::gil_scoped_acquire gil;
        try
          {
            cb_(line_);
          }
        catch (const py::error_already_set &)
          {
            failed_ = true;
          }
      }
    line_.clear();
    return c;
  }
} // namespace gearfem::python
