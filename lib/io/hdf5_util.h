#pragma once
// Internal to lib/io: the one HDF5 layer of gearfem's file contracts (mesh tables,
// solve results). The HDF5 C API directly: no deal.II (io is a light module), and unlike
// dealii::HDF5, whose destructors call MPI_Abort when an exception unwinds through an open
// file, every failure here is an exception the CLI turns into a named error.
#include "base/errors.h"
#include "base/number.h"

#include <hdf5.h>

#include <cmath>
#include <ctime>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::io::hdf5
{
  inline std::string utc_now()
  {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
  }

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
      if (!std::isfinite(x))
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

    /// A 1-D dataset of variable-length UTF-8 strings.
    void string_dataset(hid_t group, const char *name, const std::vector<std::string> &data) const
    {
    Hid type(ok_id(H5Tcopy(H5T_C_S1), name), H5Tclose);
    ok(H5Tset_size(type.get(), H5T_VARIABLE), name);
    ok(H5Tset_cset(type.get(), H5T_CSET_UTF8), name);
    const hsize_t n = data.size();
    Hid space(ok_id(H5Screate_simple(1, &n, nullptr), name), H5Sclose);
    Hid set(ok_id(H5Dcreate2(group, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT),
                  name),
            H5Dclose);
    std::vector<const char *> p(data.size());
    for (std::size_t i = 0; i < data.size(); ++i)
      p[i] = data[i].c_str();
    if (n > 0)
      ok(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()), name);
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
    /// `kind` names the file in messages, e.g. "mesh table file".
    Reader(std::string file, std::string kind)
    : file_(std::move(file))
    , kind_(std::move(kind))
    {}

    std::string item(const std::string &object, const std::string &attribute = "") const
    {
    return kind_ + " " + file_ + ": " + object +
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
    std::vector<double> v;
    dataset_into(group, group_path, name, rank, dims, [&](hsize_t n) {
      v.resize(n);
      return v.data();
    }, hint);
    return v;
    }

    /// The same, read into the storage that `storage(n)` returns for its n values (row-major),
    /// without an intermediate copy.
    template <typename Storage>
    void dataset_into(hid_t group, const std::string &group_path, const char *name, int rank,
                      std::vector<hsize_t> &dims, const Storage &storage, const std::string &hint = "") const
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
    double *to = storage(n);
    if (n > 0 && H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, to) < 0)
      fail(object, "", "unreadable", expected, "corrupt or truncated file?");
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
    std::string file_, kind_;
  };
} // namespace gearfem::io::hdf5
