#include "io/mesh_table_io.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"

#include <hdf5.h>

#include <cmath>
#include <ctime>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gearfem::io
{
  namespace
  {
    using dynamics::MeshTable;

    /// Owns an HDF5 identifier and closes it with the matching H5xclose.
    class Hid
    {
    public:
      using Closer = herr_t (*)(hid_t);
      Hid(hid_t id, Closer closer)
        : id_(id)
        , close_(closer)
      {}
      Hid(Hid &&other) noexcept
        : id_(std::exchange(other.id_, -1))
        , close_(other.close_)
      {}
      Hid(const Hid &) = delete;
      Hid &operator=(const Hid &) = delete;
      Hid &operator=(Hid &&) = delete;
      ~Hid() { close(); }
      hid_t get() const { return id_; }
      bool valid() const { return id_ >= 0; }
      /// Close now; returns the HDF5 status (negative on failure).
      herr_t close()
      {
        herr_t r = 0;
        if (id_ >= 0)
          r = close_(id_);
        id_ = -1;
        return r;
      }

    private:
      hid_t id_;
      Closer close_;
    };

    /// Turns off HDF5's printing of its error stack while alive: we report our own errors.
    class QuietHdf5
    {
    public:
      QuietHdf5()
      {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
      }
      ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
      QuietHdf5(const QuietHdf5 &) = delete;
      QuietHdf5 &operator=(const QuietHdf5 &) = delete;

    private:
      H5E_auto2_t func_ = nullptr;
      void *data_ = nullptr;
    };

    using Kind = MeshTable::Kind;
    // Names and units of docs/mesh-tables.md (one definition, in dynamics/mesh_force.h).
    const auto second_name = dynamics::second_axis_name;
    const auto second_unit = dynamics::second_axis_unit;
    const auto value_unit  = dynamics::value_axis_unit;
    const auto quantity    = dynamics::value_quantity;

    std::string utc_now()
    {
      const std::time_t t = std::time(nullptr);
      std::tm tm{};
      gmtime_r(&t, &tm);
      char buf[32];
      std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
      return buf;
    }

    // ---------------------------------------------------------------- writing

    /// Writes the objects of one file; every HDF5 failure throws std::runtime_error.
    class Writer
    {
    public:
      explicit Writer(std::string file)
        : file_(std::move(file))
      {}

      void ok(herr_t status, const std::string &what) const
      {
        if (status < 0)
          throw std::runtime_error("HDF5 write failed (" + what + ") for " + file_);
      }
      hid_t ok_id(hid_t id, const std::string &what) const
      {
        if (id < 0)
          throw std::runtime_error("HDF5 write failed (" + what + ") for " + file_);
        return id;
      }

      void string_attribute(hid_t obj, const char *name, const std::string &value) const
      {
        Hid type(ok_id(H5Tcopy(H5T_C_S1), name), H5Tclose);
        ok(H5Tset_size(type.get(), H5T_VARIABLE), name);
        ok(H5Tset_cset(type.get(), H5T_CSET_UTF8), name);
        Hid space(ok_id(H5Screate(H5S_SCALAR), name), H5Sclose);
        Hid attr(ok_id(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                       name),
                 H5Aclose);
        const char *p = value.c_str();
        ok(H5Awrite(attr.get(), type.get(), &p), name);
      }

      void double_attribute(hid_t obj, const char *name, double value) const
      {
        require_finite_output(value, file_, std::string("attribute '") + name + "'");
        Hid space(ok_id(H5Screate(H5S_SCALAR), name), H5Sclose);
        Hid attr(ok_id(H5Acreate2(obj, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                  H5P_DEFAULT),
                       name),
                 H5Aclose);
        ok(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), name);
      }

      void int_attribute(hid_t obj, const char *name, int value) const
      {
        Hid space(ok_id(H5Screate(H5S_SCALAR), name), H5Sclose);
        Hid attr(ok_id(H5Acreate2(obj, name, H5T_STD_I32LE, space.get(), H5P_DEFAULT,
                                  H5P_DEFAULT),
                       name),
                 H5Aclose);
        ok(H5Awrite(attr.get(), H5T_NATIVE_INT, &value), name);
      }

      /// A float64 dataset of shape `dims` with attribute unit (and quantity if not empty).
      void dataset(hid_t group, const char *name, const std::vector<hsize_t> &dims,
                   const std::vector<double> &data, const std::string &unit,
                   const std::string &quantity_value = "") const
      {
        for (const double x : data)
          require_finite_output(x, file_, std::string("dataset '") + name + "'");
        Hid space(ok_id(H5Screate_simple(int(dims.size()), dims.data(), nullptr), name),
                  H5Sclose);
        Hid set(ok_id(H5Dcreate2(group, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT),
                      name),
                H5Dclose);
        ok(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
           name);
        string_attribute(set.get(), "unit", unit);
        if (!quantity_value.empty())
          string_attribute(set.get(), "quantity", quantity_value);
      }

    private:
      std::string file_;
    };

    // ---------------------------------------------------------------- reading

    /// Reads the objects of one file; every problem throws InputError naming the file and
    /// the dataset or attribute.
    class Reader
    {
    public:
      explicit Reader(std::string file)
        : file_(std::move(file))
      {}

      std::string item(const std::string &object, const std::string &attribute = "") const
      {
        return "mesh table file " + file_ + ": " + object +
               (attribute.empty() ? "" : " attribute '" + attribute + "'");
      }

      [[noreturn]] void fail(const std::string &object, const std::string &attribute,
                             const std::string &value, const std::string &allowed,
                             const std::string &detail = "") const
      {
        throw InputError(item(object, attribute), value, allowed, detail);
      }

      Hid open_attribute(hid_t obj, const std::string &object, const char *name,
                         const std::string &expected) const
      {
        const htri_t e = H5Aexists(obj, name);
        if (e <= 0)
          fail(object, name, e < 0 ? "unreadable" : "missing", expected);
        Hid attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
        if (!attr.valid())
          fail(object, name, "unreadable", expected, "corrupt file?");
        Hid space(H5Aget_space(attr.get()), H5Sclose);
        if (!space.valid() || H5Sget_simple_extent_npoints(space.get()) != 1)
          fail(object, name, "not a single value", expected);
        return attr;
      }

      H5T_class_t type_class(hid_t attr) const
      {
        Hid type(H5Aget_type(attr), H5Tclose);
        return type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
      }

      std::string string_attribute(hid_t obj, const std::string &object, const char *name) const
      {
        Hid attr = open_attribute(obj, object, name, "a string");
        Hid type(H5Aget_type(attr.get()), H5Tclose);
        if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING)
          fail(object, name, "not a string", "a string");
        Hid mem(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
        std::string s;
        if (H5Tis_variable_str(type.get()) > 0)
          {
            H5Tset_size(mem.get(), H5T_VARIABLE);
            char *p = nullptr;
            if (H5Aread(attr.get(), mem.get(), &p) < 0)
              fail(object, name, "unreadable", "a string", "corrupt file?");
            if (p)
              s = p;
            Hid space(H5Screate(H5S_SCALAR), H5Sclose);
#if H5_VERSION_GE(1, 12, 0)
            H5Treclaim(mem.get(), space.get(), H5P_DEFAULT, &p);
#else
            H5Dvlen_reclaim(mem.get(), space.get(), H5P_DEFAULT, &p);
#endif
          }
        else
          {
            const std::size_t n = H5Tget_size(type.get());
            H5Tset_size(mem.get(), n);
            std::string buf(n, '\0');
            if (n > 0 && H5Aread(attr.get(), mem.get(), buf.data()) < 0)
              fail(object, name, "unreadable", "a string", "corrupt file?");
            s = buf.substr(0, buf.find('\0'));
            while (!s.empty() && s.back() == ' ')
              s.pop_back();
          }
        return s;
      }

      double double_attribute(hid_t obj, const std::string &object, const char *name,
                              const std::string &unit) const
      {
        const std::string expected = "a finite number [" + unit + "]";
        Hid attr = open_attribute(obj, object, name, expected);
        const H5T_class_t c = type_class(attr.get());
        if (c != H5T_FLOAT && c != H5T_INTEGER)
          fail(object, name, "not a number", expected);
        double v = 0;
        if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v) < 0)
          fail(object, name, "unreadable", expected, "corrupt file?");
        if (!std::isfinite(v))
          fail(object, name, to_string_g(v), expected);
        return v;
      }

      long long integer_attribute(hid_t obj, const std::string &object, const char *name,
                                  const std::string &expected) const
      {
        Hid attr = open_attribute(obj, object, name, expected);
        if (type_class(attr.get()) != H5T_INTEGER)
          fail(object, name, "not an integer", expected);
        long long v = 0;
        if (H5Aread(attr.get(), H5T_NATIVE_LLONG, &v) < 0)
          fail(object, name, "unreadable", expected, "corrupt file?");
        return v;
      }

      /// The float64 (or integer) dataset `name` of `group`, of rank `rank`.
      std::vector<double> dataset(hid_t group, const std::string &group_path, const char *name,
                                  int rank, std::vector<hsize_t> &dims,
                                  const std::string &hint = "") const
      {
        const std::string object = group_path + "/" + name;
        const std::string expected = std::to_string(rank) + "-D float64 dataset";
        const htri_t e = H5Lexists(group, name, H5P_DEFAULT);
        if (e <= 0)
          fail(object, "", e < 0 ? "unreadable" : "missing", expected, hint);
        Hid set(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
        if (!set.valid())
          fail(object, "", "not a dataset or unreadable", expected, "corrupt file?");
        Hid type(H5Dget_type(set.get()), H5Tclose);
        const H5T_class_t c = type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
        if (c != H5T_FLOAT && c != H5T_INTEGER)
          fail(object, "", "not numeric", expected);
        Hid space(H5Dget_space(set.get()), H5Sclose);
        const int r = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
        if (r != rank)
          fail(object, "", "rank " + std::to_string(r), expected);
        dims.assign(rank, 0);
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
        hsize_t n = 1;
        for (hsize_t d : dims)
          n *= d;
        std::vector<double> v(n);
        if (n > 0 &&
            H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
          fail(object, "", "unreadable", expected, "corrupt or truncated file?");
        return v;
      }

      /// Open `name` (an object path) as a dataset only to read its string attribute.
      std::string dataset_string_attribute(hid_t group, const std::string &group_path,
                                           const char *name, const char *attribute) const
      {
        Hid set(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
        if (!set.valid())
          fail(group_path + "/" + name, "", "not a dataset or unreadable", "a dataset");
        return string_attribute(set.get(), group_path + "/" + name, attribute);
      }

      void require_unit(hid_t group, const std::string &group_path, const char *name,
                        const std::string &unit) const
      {
        const std::string u = dataset_string_attribute(group, group_path, name, "unit");
        if (u != unit)
          fail(group_path + "/" + name, "unit", u.empty() ? "(empty)" : u, unit,
               "tables are stored in SI units");
      }

    private:
      std::string file_;
    };
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

    const Reader r(name);
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
