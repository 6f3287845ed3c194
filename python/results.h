#pragma once
// Results of the Python module (python/module.cc): the solve-results tables as dicts of numpy
// arrays keyed by the CSV column names, the run record as a dict; and the progress stream that
// hands the library's progress lines to a Python callable.
#include "base/table.h"
#include "route/route.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace gearfem::python
{
  struct Results
  {
    pybind11::dict sweep, pairs, pressure, line_of_action; ///< column name [unit] -> numpy array
    pybind11::dict run;                                    ///< run.json's members: route, cost, ...
    std::string route;                                     ///< the route taken (route::to_string)
  };

  /// A table as {"name [unit]": numpy array}, in column order.
  pybind11::dict table_dict(const Table &t);
  Results results_of(const route::Outcome &o);
  void bind_results(pybind11::module_ &m);

  /// An ostream whose lines go to a Python callable (the GIL taken per line); get() is null
  /// without a callable, so that the library stays silent. An exception the callable raises
  /// stops further calls and is dropped (progress never fails a solve).
  class ProgressStream
  {
  public:
    explicit ProgressStream(const pybind11::object &callback);
    ~ProgressStream();
    std::ostream *get() { return stream_.get(); }

  private:
    class Buffer : public std::streambuf
    {
    public:
      explicit Buffer(pybind11::object cb) : cb_(std::move(cb)) {}
      ~Buffer() override;

    protected:
      int overflow(int c) override;

    private:
      pybind11::object cb_;
      std::string line_;
      bool failed_ = false;
    };
    std::unique_ptr<Buffer> buffer_;
    std::unique_ptr<std::ostream> stream_;
  };
} // namespace gearfem::python
