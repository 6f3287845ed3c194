// MeshTable checks and the axis names of the mesh-table contract (docs/mesh-tables.md).
#include "io/mesh_table.h"

#include "base/errors.h"
#include "base/number.h"

#include <algorithm>
#include <cmath>

namespace gearfem::io
{
  const char *second_axis_name(MeshTable::Kind k)
  {
    return k == MeshTable::Kind::torque_vs_compression ? "delta" :
           k == MeshTable::Kind::stiffness_vs_load     ? "load" :
                                                        "torque";
  }
  const char *second_axis_unit(MeshTable::Kind k)
  {
    return k == MeshTable::Kind::torque_vs_compression ? "m" :
           k == MeshTable::Kind::stiffness_vs_load     ? "N" :
                                                        "N*m";
  }
  const char *value_axis_unit(MeshTable::Kind k)
  {
    return k == MeshTable::Kind::torque_vs_compression ? "N*m" :
           k == MeshTable::Kind::stiffness_vs_load     ? "N/m" :
                                                        "m";
  }
  const char *value_quantity(MeshTable::Kind k)
  {
    return k == MeshTable::Kind::torque_vs_compression ? "torque" :
           k == MeshTable::Kind::stiffness_vs_load     ? "stiffness" :
                                                        "transmission error";
  }

  long node_at(const std::vector<double> &axis, double x)
  {
    const double tol = 1e-9 * (axis.back() - axis.front());
    for (std::size_t j = 0; j < axis.size(); ++j)
      if (std::abs(axis[j] - x) <= tol)
        return long(j);
    return -1;
  }

  void MeshTable::check(const std::string &expected_hash) const
  {
    const bool torque = kind == Kind::torque_vs_compression;
    const std::string sname = second_axis_name(kind);
    if (theta.size() < 2)
      throw InputError("mesh table/theta axis", std::to_string(theta.size()) + " nodes",
                       ">= 2 nodes", "missing or too short theta axis");
    if (second.size() < 2)
      throw InputError("mesh table/" + sname + " axis",
                       std::to_string(second.size()) + " nodes", ">= 2 nodes",
                       "missing or too short second axis");
    if (values.size() != theta.size() * second.size())
      throw InputError("mesh table/values", std::to_string(values.size()) + " values",
                       std::to_string(theta.size() * second.size()) + " (theta x second axis)");
    if (theta_unit != "rad")
      throw InputError("mesh table/theta unit", theta_unit, "rad");
    if (second_unit != second_axis_unit(kind))
      throw InputError("mesh table/second-axis unit", second_unit, second_axis_unit(kind));
    if (value_unit != value_axis_unit(kind))
      throw InputError("mesh table/value unit", value_unit, value_axis_unit(kind));
    for (std::size_t i = 1; i < theta.size(); ++i)
      if (!(theta[i] > theta[i - 1]))
        throw InputError("mesh table/theta axis", "not strictly increasing", "increasing");
    for (std::size_t i = 1; i < second.size(); ++i)
      if (!(second[i] > second[i - 1]))
        throw InputError("mesh table/second axis", "not strictly increasing", "increasing");
    if (backlash >= 0 && !torque)
      throw InputError("mesh table/backlash", to_string_g(backlash),
                       "only torque tables T(theta, delta) are two-sided");
    if (second[0] < 0 && !two_sided())
      throw InputError("mesh table/" + sname + " axis", to_string_g(second[0]), ">= 0",
                       "negative compressions need a two-sided table (backlash >= 0)");
    if (two_sided())
      {
        const long j0 = node_at(second, 0.0), jb = node_at(second, -backlash);
        if (!(second[0] < -backlash) || j0 < 0 || jb < 0 || j0 + 1 >= long(second.size()))
          throw InputError("mesh table/delta axis",
                           "[" + to_string_g(second.front()) + ", " + to_string_g(second.back()) + "] m",
                           "nodes below -b, at -b = " + to_string_g(-backlash) + " m, at 0 and above 0",
                           "a two-sided table covers the reverse flank, the gap and the drive flank");
        double scale = 0;
        for (double v : values)
          scale = std::max(scale, std::abs(v));
        for (std::size_t i = 0; i < theta.size(); ++i)
          for (std::size_t j = 0; j < second.size(); ++j)
            {
              const double v = value(i, j);
              const bool gap = long(j) >= jb && long(j) <= j0;
              if ((gap && std::abs(v) > 1e-12 * scale) || (long(j) < jb && v > 1e-12 * scale) ||
                  (long(j) > j0 && v < -1e-12 * scale))
                throw InputError("mesh table/values", to_string_g(v) + " N*m at delta = " +
                                                        to_string_g(second[j]) + " m",
                                 gap ? "0 on [-b, 0] (loss of contact)" :
                                       (long(j) < jb ? "<= 0 below -b (reverse flank)" : ">= 0 above 0"));
            }
      }
    else if (second[0] < 0)
      throw InputError("mesh table/second axis", to_string_g(second[0]), ">= 0");
    if (!(period > 0) || theta.back() - theta.front() >= period)
      throw InputError("mesh table/period", to_string_g(period),
                       "> 0 and longer than the theta axis span");
    if (!(base_radius > 0))
      throw InputError("mesh table/base radius", to_string_g(base_radius), "> 0 m");
    for (double v : values)
      if (!std::isfinite(v) || (!torque && v <= 0))
        throw InputError("mesh table/values", to_string_g(v),
                         torque ? "finite" : "finite and > 0");
    if (!expected_hash.empty() && geometry_hash != expected_hash)
      throw InputError("mesh table/geometry hash", geometry_hash, expected_hash,
                       "the table was computed for another gear pair");
  }

  void MeshTable::require_covers_load(double F) const
  {
    if (kind == Kind::ste_vs_torque)
      {
        const double T = F * base_radius;
        if (T < second.front() || T > second.back())
          throw InputError("mesh table/torque range", to_string_g(T) + " N*m",
                           "[" + to_string_g(second.front()) + ", " + to_string_g(second.back()) +
                             "] N*m",
                           "the table does not cover the requested load");
        return;
      }
    if (kind == Kind::stiffness_vs_load)
      {
        if (F < second.front() || F > second.back())
          throw InputError("mesh table/load range", to_string_g(F) + " N",
                           "[" + to_string_g(second.front()) + ", " + to_string_g(second.back()) +
                             "] N",
                           "the table does not cover the requested load");
        return;
      }
    // Torque table: the static torque F r_b1 must lie below the smallest row maximum.
    double tmax = 1e300;
    for (std::size_t i = 0; i < theta.size(); ++i)
      tmax = std::min(tmax, value(i, second.size() - 1));
    if (F * base_radius > tmax)
      throw InputError("mesh table/load range", to_string_g(F * base_radius) + " N*m",
                       "<= " + to_string_g(tmax) + " N*m",
                       "the table does not cover the requested load");
  }
  std::vector<double> torque_table_axis(const std::vector<double> &drive, double backlash)
  {
    if (backlash < 0)
      return drive;
    std::vector<double> axis;
    for (auto it = drive.rbegin(); it != drive.rend(); ++it)
      axis.push_back(-backlash - *it);
    if (backlash > 0)
      axis.push_back(0.0);
    axis.insert(axis.end(), drive.begin() + 1, drive.end());
    return axis;
  }
} // namespace gearfem::io
