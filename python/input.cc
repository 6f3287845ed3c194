// The Python module's inputs (python/input.h).
#include "python/input.h"

#include "base/errors.h"
#include "commands/command.h"
#include "params/checked.h"
#include "route/route.h"

#include <deal.II/base/parameter_handler.h>

#include <iomanip>
#include <sstream>

namespace py = pybind11;

namespace gearfem::python
{
  std::string prm_value(const py::handle &v)
  {
    if (py::isinstance<py::bool_>(v))
      return v.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::int_>(v))
      return std::to_string(v.cast<long long>());
    if (py::isinstance<py::float_>(v))
      {
        std::ostringstream s;
        s << std::setprecision(17) << v.cast<double>();
        return s.str();
      }
    if (py::isinstance<py::str>(v))
      return v.cast<std::string>();
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) ||
        py::hasattr(v, "tolist")) // a numpy array
      {
        const py::list items =
          py::hasattr(v, "tolist") ? py::list(v.attr("tolist")()) : py::list(py::reinterpret_borrow<py::object>(v));
        std::string s;
        for (std::size_t i = 0; i < items.size(); ++i)
          s += (i ? ", " : "") + prm_value(items[i]);
        return s;
      }
    return py::str(v).cast<std::string>();
  }

  std::string entry_text(const std::string &path, const std::string &value)
  {
    std::vector<std::string> parts;
    std::size_t a = 0;
    for (std::size_t b; (b = path.find('/', a)) != std::string::npos; a = b + 1)
      parts.push_back(path.substr(a, b - a));
    parts.push_back(path.substr(a));
    if (parts.size() < 2 || parts.back().empty())
      throw InputError("entry path", path, "Section/Entry, e.g. 'Solve/Torques'");
    if (value.find('\n') != std::string::npos)
      throw InputError(path, value, "a value on one line");
    std::string s;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
      s += "subsection " + parts[i] + "\n";
    s += "set " + parts.back() + " = " + value + "\n";
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
      s += "end\n";
    return s;
  }

  std::string sections_text(const py::dict &sections, int depth)
  {
    std::string s;
    for (const auto &[k, v] : sections)
      {
        const std::string key = py::str(k).cast<std::string>();
        if (py::isinstance<py::dict>(v))
          s += "subsection " + key + "\n" + sections_text(py::reinterpret_borrow<py::dict>(v), depth + 1) + "end\n";
        else if (depth == 0)
          throw InputError("Input.from_dict", key, "a section: a dict of entries");
        else
          s += "set " + key + " = " + prm_value(v) + "\n";
      }
    return s;
  }

  Input Input::with(const std::map<std::string, std::string> &entries) const
  {
    Input out = *this;
    if (!out.text.empty() && out.text.back() != '\n')
      out.text += '\n';
    for (const auto &[path, value] : entries)
      out.text += entry_text(path, value);
    return out;
  }

  std::string Input::get(const std::string &path) const
  {
    dealii::ParameterHandler prm;
    for (const auto &c : commands::registry())
      if (c.declare && c.parse_input)
        c.declare(prm);
    parse(*this, prm);
    std::size_t a = 0, b;
    for (; (b = path.find('/', a)) != std::string::npos; a = b + 1)
      prm.enter_subsection(path.substr(a, b - a));
    const std::string v = prm.get(path.substr(a));
    for (std::size_t i = 0; i < path.size(); ++i)
      if (path[i] == '/')
        prm.leave_subsection();
    return v;
  }

  void parse(const Input &in, dealii::ParameterHandler &prm)
  {
    commands::parse_input_text(in.text, in.name, prm);
  }
} // namespace gearfem::python
