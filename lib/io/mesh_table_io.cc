#include "io/mesh_table_io.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"

#include "io/hdf5_util.h"

#include <cmath>
#include <ctime>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gearfem::io
{
  namespace
  {
    using namespace hdf5;

    using Kind = MeshTable::Kind;
    // Names and units of docs/mesh-tables.md (one definition, in io/mesh_table.h).
    const auto second_name = second_axis_name;
    const auto second_unit = second_axis_unit;
    const auto value_unit  = value_axis_unit;
    const auto quantity    = value_quantity;


  } // namespace

  void write_mesh_table(const std::filesystem::path &file, const MeshTable &table,
                        const TableProvenance &provenance)
  {
    table.check();
    const std::size_t nt = table.theta.size(), ns = table.second.size();
    const Writer w(file.string());
    const QuietHdf5 quiet;
    TemporaryPath tmp(file);
    {
      Hid f(H5Fcreate(tmp.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      if (!f.valid())
        throw InputError("mesh table output file", file.string(),
                         "a writable path in an existing folder",
                         "cannot create " + tmp.path().string());
      w.string_attribute(f.get(), "format", mesh_table_format);
      // Version 1 whenever the file fits it, so that version-1 readers keep reading it.
      const bool v1 = table.kind != Kind::ste_vs_torque && !table.two_sided();
      w.int_attribute(f.get(), "format_version", v1 ? 1 : mesh_table_format_version);
      w.string_attribute(f.get(), "geometry_hash", table.geometry_hash);
      w.string_attribute(f.get(), "source", provenance.source);
      w.string_attribute(f.get(), "created",
                         provenance.created.empty() ? utc_now() : provenance.created);

      Hid g(w.ok_id(H5Gcreate2(f.get(), "table", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    "/table"),
            H5Gclose);
      w.double_attribute(g.get(), "period", table.period);
      w.double_attribute(g.get(), "base_radius", table.base_radius);
      if (table.two_sided())
        w.double_attribute(g.get(), "backlash", table.backlash);
      w.double_attribute(g.get(), "valid_min", table.second.front());
      w.double_attribute(g.get(), "valid_max", table.second.back());
      w.dataset(g.get(), "theta", {nt}, table.theta, "rad");
      w.dataset(g.get(), second_name(table.kind), {ns}, table.second, second_unit(table.kind));
      w.dataset(g.get(), "values", {nt, ns}, table.values, value_unit(table.kind),
                quantity(table.kind));
      g.close();
      w.ok(H5Fflush(f.get(), H5F_SCOPE_GLOBAL), "flush");
      w.ok(f.close(), "close");
    }
    tmp.commit();
  }

  MeshTable read_mesh_table(const std::filesystem::path &file, const std::string &expected_hash,
                            MeshTableFileInfo *info)
  {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
      throw InputError("mesh table file", name, "an existing HDF5 mesh-table file",
                       "file not found");
    if (std::filesystem::is_directory(file, ec))
      throw InputError("mesh table file", name, "an HDF5 mesh-table file", "is a folder");

    const QuietHdf5 quiet;
    if (H5Fis_hdf5(name.c_str()) <= 0)
      throw InputError("mesh table file", name, "an HDF5 mesh-table file",
                       "not an HDF5 file, or corrupt");
    Hid f(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!f.valid())
      throw InputError("mesh table file", name, "a readable HDF5 mesh-table file",
                       "cannot be opened: corrupt or truncated HDF5 file");

    const Reader r(name, "mesh table file");
    const std::string format = r.string_attribute(f.get(), "/", "format");
    if (format != mesh_table_format)
      r.fail("/", "format", format, mesh_table_format, "not a gearfem mesh table");
    const std::string known = std::to_string(mesh_table_format_version);
    const long long version = r.integer_attribute(f.get(), "/", "format_version", known);
    if (version < 1 || version > mesh_table_format_version)
      r.fail("/", "format_version", std::to_string(version), "1.." + known,
             "this gearfem reads mesh-table format versions 1 to " + known +
               " (docs/mesh-tables.md)");

    MeshTable t;
    t.geometry_hash = r.string_attribute(f.get(), "/", "geometry_hash");
    MeshTableFileInfo inf;
    inf.format_version = int(version);
    inf.provenance.source = r.string_attribute(f.get(), "/", "source");
    inf.provenance.created = r.string_attribute(f.get(), "/", "created");

    const htri_t has_table = H5Lexists(f.get(), "table", H5P_DEFAULT);
    if (has_table <= 0)
      r.fail("/table", "", "missing", "a group with theta, delta or load, and values");
    Hid g(H5Gopen2(f.get(), "table", H5P_DEFAULT), H5Gclose);
    if (!g.valid())
      r.fail("/table", "", "not a group or unreadable", "a group");
    const std::string gp = "/table";

    // The quantity of the values decides which second axis the table has.
    std::vector<hsize_t> dims_t, dims_s, dims_v;
    t.theta = r.dataset(g.get(), gp, "theta", 1, dims_t);
    r.require_unit(g.get(), gp, "theta", "rad");
    t.values = r.dataset(g.get(), gp, "values", 2, dims_v);
    const std::string q = r.dataset_string_attribute(g.get(), gp, "values", "quantity");
    if (q == "torque")
      t.kind = MeshTable::Kind::torque_vs_compression;
    else if (q == "stiffness")
      t.kind = MeshTable::Kind::stiffness_vs_load;
    else if (q == "transmission error" && version >= 2)
      t.kind = MeshTable::Kind::ste_vs_torque;
    else
      r.fail(gp + "/values", "quantity", q.empty() ? "(empty)" : q,
             version >= 2 ? "{torque, stiffness, transmission error}" : "{torque, stiffness} (version 1)");
    const char *sn = second_name(t.kind);
    t.second = r.dataset(g.get(), gp, sn, 1, dims_s,
                         std::string("quantity = ") + q + " needs the second axis " + sn);
    r.require_unit(g.get(), gp, sn, second_unit(t.kind));
    r.require_unit(g.get(), gp, "values", value_unit(t.kind));
    if (dims_v[0] != dims_t[0] || dims_v[1] != dims_s[0])
      r.fail(gp + "/values", "",
             "shape [" + std::to_string(dims_v[0]) + "][" + std::to_string(dims_v[1]) + "]",
             "[" + std::to_string(dims_t[0]) + "][" + std::to_string(dims_s[0]) +
               "] = [n_theta][n_" + sn + "]");
    t.theta_unit = "rad";
    t.second_unit = second_unit(t.kind);
    t.value_unit = value_unit(t.kind);

    t.period = r.double_attribute(g.get(), gp, "period", "rad");
    t.base_radius = r.double_attribute(g.get(), gp, "base_radius", "m");
    // Version 2: a torque table whose delta axis starts below 0 is two-sided and must say
    // its backlash.
    if (t.kind == Kind::torque_vs_compression && !t.second.empty() && t.second.front() < 0)
      {
        if (version < 2)
          r.fail(gp + "/delta", "", to_string_g(t.second.front()) + " m", ">= 0 in format version 1",
                 "negative compressions (two-sided tables) need format version 2");
        t.backlash = r.double_attribute(g.get(), gp, "backlash", "m");
        if (!(t.backlash >= 0))
          r.fail(gp, "backlash", to_string_g(t.backlash), ">= 0 m");
      }
    inf.valid_min = r.double_attribute(g.get(), gp, "valid_min", second_unit(t.kind));
    inf.valid_max = r.double_attribute(g.get(), gp, "valid_max", second_unit(t.kind));
    if (!(inf.valid_min <= inf.valid_max))
      r.fail(gp, "valid_max", to_string_g(inf.valid_max),
             ">= valid_min = " + to_string_g(inf.valid_min));

    if (!expected_hash.empty() && t.geometry_hash != expected_hash)
      r.fail("/", "geometry_hash", t.geometry_hash.empty() ? "(empty)" : t.geometry_hash,
             expected_hash, "the table was computed for another gear pair");
    try
      {
        t.check(expected_hash);
      }
    catch (const InputError &e)
      {
        throw InputError("mesh table file " + name + ": " + e.what());
      }
    if (!t.second.empty() &&
        (inf.valid_min < t.second.front() || inf.valid_max > t.second.back()))
      r.fail(gp, "valid_min/valid_max",
             "[" + to_string_g(inf.valid_min) + ", " + to_string_g(inf.valid_max) + "]",
             "inside the axis range [" + to_string_g(t.second.front()) + ", " +
               to_string_g(t.second.back()) + "] " + second_unit(t.kind));
    if (info)
      *info = inf;
    return t;
  }
} // namespace gearfem::io
