// HDF5 mesh-table files: exact round trip, identical TableLaw forces, an independent
// writer (the HDF5 C API with fixed-length strings, as a Python h5py user may write),
// every bad-input case named in the error, and atomic writes.
#include "base/errors.h"
#include "base/units.h"
#include "dynamics/mesh_force.h"
#include "io/mesh_table_io.h"

#include <gtest/gtest.h>

#include <limits>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using gearfem::InputError;
using gearfem::dynamics::MeshTable;
using gearfem::dynamics::TableLaw;
using gearfem::dynamics::ThetaInterpolation;
using gearfem::io::MeshTableFileInfo;
using gearfem::io::read_mesh_table;
using gearfem::io::TableProvenance;
using gearfem::io::write_mesh_table;

namespace
{
  /// A fresh folder per test, removed afterwards.
  class MeshTableIo : public ::testing::Test
  {
  protected:
    void SetUp() override
    {
      static int counter = 0;
      dir_ = fs::temp_directory_path() /
             ("gearfem_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
      fs::remove_all(dir_);
      fs::create_directories(dir_);
    }
    void TearDown() override
    {
      std::error_code ec;
      fs::remove_all(dir_, ec);
    }
    fs::path dir_;
  };

  /// Torque table T = r_b k(theta) delta on a uniform periodic theta grid, with numbers
  /// that have no short binary form (so that an exact round trip is a real test).
  MeshTable torque_table()
  {
    MeshTable t;
    t.kind = MeshTable::Kind::torque_vs_compression;
    t.period = 2 * gearfem::units::pi / 32;
    t.base_radius = 0.045105 / 3.0 * 3.0 + 1.0 / 3.0 * 1e-6;
    const int nt = 16;
    for (int i = 0; i < nt; ++i)
      t.theta.push_back(-0.3 * t.period + t.period * i / nt);
    t.second = {0.0, 1.0 / 3.0 * 1e-5, 1e-5, 2.0 / 7.0 * 1e-4};
    for (int i = 0; i < nt; ++i)
      for (double d : t.second)
        t.values.push_back(t.base_radius * 4e8 * (1 + 0.2 * std::cos(32 * t.theta[i])) * d *
                           (1 + d / 7e-5));
    t.theta_unit = "rad", t.second_unit = "m", t.value_unit = "N*m";
    t.geometry_hash = "sha256:3f9a0c1d";
    return t;
  }

  /// Stiffness table k(theta, F) [N/m], F/k increasing in F (a monotone load curve).
  MeshTable stiffness_table()
  {
    MeshTable t;
    t.kind = MeshTable::Kind::stiffness_vs_load;
    t.period = 2 * gearfem::units::pi / 20;
    t.base_radius = 0.0281907;
    const int nt = 12;
    for (int i = 0; i < nt; ++i)
      t.theta.push_back(-0.45 * t.period + t.period * i / nt);
    t.second = {50.0, 100.0 / 3.0 * 10, 1000.0, 2500.5};
    for (int i = 0; i < nt; ++i)
      for (double F : t.second)
        t.values.push_back(3.1e8 * (1 + 0.15 * std::sin(20 * t.theta[i])) * (1 + F / 1.7e4));
    t.theta_unit = "rad", t.second_unit = "N", t.value_unit = "N/m";
    t.geometry_hash = "pair-50-50";
    return t;
  }

  /// What the independent writer changes from a valid file.
  struct Spec
  {
    std::string format = "gearfem-mesh-table";
    int version = 1;
    bool version_as_string = false;
    bool theta = true, second = true, values = true, period = true;
    std::string theta_unit = "rad", second_unit, value_unit, quantity;
    int extra_rows = 0; ///< values gets this many more rows than theta has nodes
  };

  // The independent writer: plain HDF5 C API, fixed-length strings.
  void raw_string(hid_t obj, const char *name, const std::string &v)
  {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, std::max<std::size_t>(v.size(), 1));
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    std::string buf = v;
    buf.resize(std::max<std::size_t>(v.size(), 1), '\0');
    H5Awrite(a, type, buf.data());
    H5Aclose(a), H5Sclose(space), H5Tclose(type);
  }
  void raw_double(hid_t obj, const char *name, double v)
  {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(obj, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a), H5Sclose(space);
  }
  void raw_int(hid_t obj, const char *name, int v)
  {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(obj, name, H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, &v);
    H5Aclose(a), H5Sclose(space);
  }
  void raw_dataset(hid_t g, const char *name, std::vector<hsize_t> dims,
                   const std::vector<double> &v, const std::string &unit,
                   const std::string &quantity = "")
  {
    const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
    const hid_t d =
      H5Dcreate2(g, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    raw_string(d, "unit", unit);
    if (!quantity.empty())
      raw_string(d, "quantity", quantity);
    H5Dclose(d), H5Sclose(space);
  }

  void write_raw(const fs::path &file, const MeshTable &t, Spec s)
  {
    const bool torque = t.kind == MeshTable::Kind::torque_vs_compression;
    if (s.second_unit.empty())
      s.second_unit = torque ? "m" : "N";
    if (s.value_unit.empty())
      s.value_unit = torque ? "N*m" : "N/m";
    if (s.quantity.empty())
      s.quantity = torque ? "torque" : "stiffness";
    const hid_t f = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    raw_string(f, "format", s.format);
    if (s.version_as_string)
      raw_string(f, "format_version", std::to_string(s.version));
    else
      raw_int(f, "format_version", s.version);
    raw_string(f, "geometry_hash", t.geometry_hash);
    raw_string(f, "source", "independent writer");
    raw_string(f, "created", "2026-01-02T03:04:05Z");
    const hid_t g = H5Gcreate2(f, "table", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (s.period)
      raw_double(g, "period", t.period);
    raw_double(g, "base_radius", t.base_radius);
    raw_double(g, "valid_min", t.second.front());
    raw_double(g, "valid_max", t.second.back());
    const hsize_t nt = t.theta.size(), ns = t.second.size();
    if (s.theta)
      raw_dataset(g, "theta", {nt}, t.theta, s.theta_unit);
    if (s.second)
      raw_dataset(g, torque ? "delta" : "load", {ns}, t.second, s.second_unit);
    if (s.values)
      {
        std::vector<double> v = t.values;
        v.resize((nt + s.extra_rows) * ns, 1.0);
        raw_dataset(g, "values", {nt + s.extra_rows, ns}, v, s.value_unit, s.quantity);
      }
    H5Gclose(g);
    H5Fclose(f);
  }

  void expect_same(const MeshTable &a, const MeshTable &b)
  {
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.theta, b.theta); // exact: every bit
    EXPECT_EQ(a.second, b.second);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.period, b.period);
    EXPECT_EQ(a.base_radius, b.base_radius);
    EXPECT_EQ(a.geometry_hash, b.geometry_hash);
    EXPECT_EQ(a.theta_unit, b.theta_unit);
    EXPECT_EQ(a.second_unit, b.second_unit);
    EXPECT_EQ(a.value_unit, b.value_unit);
  }

  /// Reading `file` throws InputError whose message holds the file name and every piece.
  void expect_input_error(const fs::path &file, std::initializer_list<std::string> pieces,
                          const std::string &expected_hash = "")
  {
    try
      {
        read_mesh_table(file, expected_hash);
        ADD_FAILURE() << "no InputError for " << file;
      }
    catch (const InputError &e)
      {
        const std::string m = e.what();
        EXPECT_NE(m.find(file.string()), std::string::npos) << m;
        for (const std::string &p : pieces)
          EXPECT_NE(m.find(p), std::string::npos) << "'" << p << "' not in: " << m;
      }
    catch (const std::exception &e)
      {
        ADD_FAILURE() << "not an InputError: " << e.what();
      }
  }
} // namespace

// The file keeps every number bit for bit, and the provenance.
TEST_F(MeshTableIo, RoundTripIsExact)
{
  for (const MeshTable &t : {torque_table(), stiffness_table()})
    {
      const fs::path file = dir_ / "table.h5";
      write_mesh_table(file, t, {"gearfem mesh-table pair.prm", "2026-11-21T12:00:00Z"});
      MeshTableFileInfo info;
      const MeshTable r = read_mesh_table(file, t.geometry_hash, &info);
      expect_same(t, r);
      EXPECT_EQ(info.format_version, 1);
      EXPECT_EQ(info.provenance.source, "gearfem mesh-table pair.prm");
      EXPECT_EQ(info.provenance.created, "2026-11-21T12:00:00Z");
      EXPECT_EQ(info.valid_min, t.second.front());
      EXPECT_EQ(info.valid_max, t.second.back());
    }
}

// An empty timestamp is filled with the current UTC time, ISO 8601.
TEST_F(MeshTableIo, CreatedDefaultsToNow)
{
  const fs::path file = dir_ / "t.h5";
  write_mesh_table(file, torque_table(), {"test", ""});
  MeshTableFileInfo info;
  read_mesh_table(file, "", &info);
  const std::string &c = info.provenance.created;
  ASSERT_EQ(c.size(), 20u) << c;
  EXPECT_EQ(c[4], '-');
  EXPECT_EQ(c[10], 'T');
  EXPECT_EQ(c[19], 'Z');
}

// The dynamics cannot tell a table read from a file from the one in memory.
TEST_F(MeshTableIo, TableLawForcesIdentical)
{
  for (const MeshTable &t : {torque_table(), stiffness_table()})
    for (auto interp : {ThetaInterpolation::linear, ThetaInterpolation::monotone_cubic})
      {
        const fs::path file = dir_ / "law.h5";
        write_mesh_table(file, t, {"test", ""});
        const TableLaw a(t, interp), b(read_mesh_table(file), interp);
        EXPECT_EQ(a.mean_stiffness(), b.mean_stiffness());
        EXPECT_EQ(a.delta_max(), b.delta_max());
        for (int i = -40; i <= 140; ++i)
          for (int j = -2; j <= 30; ++j)
            {
              const double th = t.period * i / 37.0, d = a.delta_max() * j / 25.0;
              EXPECT_EQ(a.force(th, d, 0), b.force(th, d, 0)) << th << " " << d;
            }
      }
}

// A file written without this library (fixed-length strings, 64-bit integer version,
// as h5py may write them) reads to the same table.
TEST_F(MeshTableIo, ReadsIndependentWriter)
{
  for (const MeshTable &t : {torque_table(), stiffness_table()})
    {
      const fs::path file = dir_ / "raw.h5";
      write_raw(file, t, {});
      MeshTableFileInfo info;
      expect_same(t, read_mesh_table(file, "", &info));
      EXPECT_EQ(info.provenance.source, "independent writer");
      fs::remove(file);
    }
}

TEST_F(MeshTableIo, MissingFile)
{
  expect_input_error(dir_ / "nothing.h5", {"not found"});
}

TEST_F(MeshTableIo, NotHdf5)
{
  const fs::path file = dir_ / "table.h5";
  std::ofstream(file) << "theta,delta,torque\n0,0,0\n";
  expect_input_error(file, {"not an HDF5 file"});
}

TEST_F(MeshTableIo, TruncatedFile)
{
  const fs::path file = dir_ / "table.h5";
  write_mesh_table(file, torque_table(), {"test", ""});
  fs::resize_file(file, fs::file_size(file) / 2);
  expect_input_error(file, {});
}

TEST_F(MeshTableIo, MissingAxesOrValues)
{
  const fs::path file = dir_ / "bad.h5";
  Spec s;
  s.theta = false;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/theta", "missing"});
  s = {};
  s.second = false;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/delta", "missing"});
  write_raw(file, stiffness_table(), s);
  expect_input_error(file, {"/table/load", "missing"});
  s = {};
  s.values = false;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/values", "missing"});
  s = {};
  s.period = false;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table", "'period'", "missing"});
}

TEST_F(MeshTableIo, WrongUnits)
{
  const fs::path file = dir_ / "bad.h5";
  Spec s;
  s.theta_unit = "deg";
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/theta", "'unit'", "deg", "rad"});
  s = {};
  s.second_unit = "mm";
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/delta", "'unit'", "mm"});
  s = {};
  s.value_unit = "N*mm";
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/values", "'unit'", "N*mm"});
  s = {};
  s.second_unit = "kN";
  write_raw(file, stiffness_table(), s);
  expect_input_error(file, {"/table/load", "'unit'", "kN"});
  s = {};
  s.value_unit = "N/mm";
  write_raw(file, stiffness_table(), s);
  expect_input_error(file, {"/table/values", "'unit'", "N/mm"});
  s = {};
  s.quantity = "compliance";
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/values", "'quantity'", "compliance"});
}

TEST_F(MeshTableIo, WrongFormatOrVersion)
{
  const fs::path file = dir_ / "bad.h5";
  Spec s;
  s.version = 3;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"'format_version'", "3"});
  s = {};
  s.version_as_string = true;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"'format_version'", "not an integer"});
  s = {};
  s.format = "some-other-table";
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"'format'", "some-other-table"});
}

TEST_F(MeshTableIo, SizeMismatch)
{
  const fs::path file = dir_ / "bad.h5";
  Spec s;
  s.extra_rows = 1;
  write_raw(file, torque_table(), s);
  expect_input_error(file, {"/table/values", "[17][4]", "[16][4]"});
}

TEST_F(MeshTableIo, GeometryHashMismatch)
{
  const fs::path file = dir_ / "t.h5";
  write_mesh_table(file, torque_table(), {"test", ""});
  expect_input_error(file, {"'geometry_hash'", "sha256:3f9a0c1d", "another-pair"},
                     "another-pair");
  EXPECT_NO_THROW(read_mesh_table(file, "sha256:3f9a0c1d"));
}

// A table that MeshTable::check rejects after a clean read: the message names the file.
TEST_F(MeshTableIo, InvalidContentNamesFile)
{
  const fs::path file = dir_ / "bad.h5";
  MeshTable t = torque_table();
  std::swap(t.theta[2], t.theta[3]);
  write_raw(file, t, {});
  expect_input_error(file, {"theta", "increasing"});
}

// Writing into a folder that does not exist fails and leaves nothing behind.
TEST_F(MeshTableIo, FailedWriteLeavesNoFile)
{
  const fs::path file = dir_ / "no_such_folder" / "table.h5";
  EXPECT_THROW(write_mesh_table(file, torque_table(), {"test", ""}), InputError);
  EXPECT_FALSE(fs::exists(file));
  EXPECT_FALSE(fs::exists(file.parent_path()));
}

// A failed write (invalid table) leaves an existing file untouched and no temporary
// file in the folder; a successful one replaces it.
TEST_F(MeshTableIo, FailedWriteKeepsOldFile)
{
  const fs::path file = dir_ / "table.h5";
  write_mesh_table(file, torque_table(), {"first", ""});
  const auto size = fs::file_size(file);
  MeshTable bad = torque_table();
  bad.values.pop_back();
  EXPECT_THROW(write_mesh_table(file, bad, {"second", ""}), InputError);
  int n = 0;
  for (const auto &e : fs::directory_iterator(dir_))
    {
      ++n;
      EXPECT_EQ(e.path().filename(), "table.h5");
    }
  EXPECT_EQ(n, 1);
  EXPECT_EQ(fs::file_size(file), size);
  MeshTableFileInfo info;
  read_mesh_table(file, "", &info);
  EXPECT_EQ(info.provenance.source, "first");

  write_mesh_table(file, stiffness_table(), {"third", ""});
  expect_same(stiffness_table(), read_mesh_table(file, "", &info));
  EXPECT_EQ(info.provenance.source, "third");
}

namespace
{
  /// Two-sided torque table (version 2): T = r_b k delta above 0, 0 on [-b, 0], and the
  /// reverse flank -r_b k_r (-delta - b) below -b, with k_r != k so that the branches differ.
  MeshTable two_sided_table(double b)
  {
    MeshTable t = torque_table();
    t.backlash = b;
    const std::vector<double> drive = t.second; // 0 .. delta_max
    t.second.clear();
    for (auto it = drive.rbegin(); it != drive.rend(); ++it)
      t.second.push_back(-b - *it);
    t.second.push_back(0.0);
    t.second.insert(t.second.end(), drive.begin() + 1, drive.end());
    t.values.clear();
    for (std::size_t i = 0; i < t.theta.size(); ++i)
      for (double d : t.second)
        t.values.push_back(d > 0 ? t.base_radius * 3e8 * (1 + 0.1 * std::cos(32 * t.theta[i])) * d :
                           d < -b ? -t.base_radius * 2e8 * (-d - b) : 0.0);
    return t;
  }
} // namespace

// Version 2: a two-sided torque table keeps its backlash and every number; TableLaw splits
// it into the drive branch and the reverse branch (forces from the closed form above), and
// a one-sided table is still written as version 1.
TEST_F(MeshTableIo, TwoSidedTableIsVersion2)
{
  const double b = 1.0e-4 / 3.0;
  const MeshTable t = two_sided_table(b);
  const fs::path file = dir_ / "two.h5";
  write_mesh_table(file, t, {"test", ""});
  MeshTableFileInfo info;
  const MeshTable r = read_mesh_table(file, t.geometry_hash, &info);
  expect_same(t, r);
  EXPECT_EQ(info.format_version, 2);
  EXPECT_EQ(r.backlash, b);
  const TableLaw law(r, ThetaInterpolation::linear);
  ASSERT_TRUE(law.has_reverse_branch());
  EXPECT_EQ(law.backlash(), b);
  const double th = r.theta[3], dr = 2e-6; // on a theta node: interpolation in delta only (linear)
  EXPECT_NEAR(law.reverse_force(th, dr), 2e8 * dr, 1e-9 * 2e8 * dr);
  EXPECT_NEAR(law.force(th, dr, 0), 3e8 * (1 + 0.1 * std::cos(32 * th)) * dr, 1e-9 * 3e8 * dr);
  const fs::path one = dir_ / "one.h5";
  write_mesh_table(one, torque_table(), {"test", ""});
  read_mesh_table(one, "", &info);
  EXPECT_EQ(info.format_version, 1);
}

// Bad two-sided tables: a torque in the gap, a positive torque on the reverse side, no node
// at -b, negative delta without a backlash, and negative delta in a version-1 file.
TEST_F(MeshTableIo, BadTwoSidedTables)
{
  const double b = 2e-5;
  MeshTable t = two_sided_table(b);
  const std::size_t ns = t.second.size(), jgap = ns / 2 - 1; // the node at -b
  t.values[jgap] = 1.0;
  EXPECT_THROW(t.check(), InputError);
  t = two_sided_table(b);
  t.values[0] = 5.0;
  EXPECT_THROW(t.check(), InputError);
  t = two_sided_table(b);
  t.backlash = 0.5 * b;
  EXPECT_THROW(t.check(), InputError);
  t = two_sided_table(b);
  t.backlash = -1;
  EXPECT_THROW(t.check(), InputError);
  const fs::path file = dir_ / "v1.h5";
  Spec s;
  s.version = 1;
  MeshTable neg = torque_table();
  for (double &d : neg.second)
    d -= 1e-6;
  write_raw(file, neg, s);
  expect_input_error(file, {"/table/delta", "format version 1"});
}

// Version 2: the transmission-error table STE(theta, T) of gearfem calibrate round-trips
// and is refused as a mesh-force law.
TEST_F(MeshTableIo, SteTable)
{
  MeshTable t = stiffness_table();
  t.kind = MeshTable::Kind::ste_vs_torque;
  t.second_unit = "N*m", t.value_unit = "m";
  for (double &v : t.values)
    v = 1e-6 / v * 1e9;
  const fs::path file = dir_ / "ste.h5";
  write_mesh_table(file, t, {"test", ""});
  MeshTableFileInfo info;
  const MeshTable r = read_mesh_table(file, t.geometry_hash, &info);
  expect_same(t, r);
  EXPECT_EQ(info.format_version, 2);
  EXPECT_THROW(TableLaw(r, ThetaInterpolation::linear), InputError);
}

// No NaN or inf reaches an HDF5 table; nothing is left behind.
TEST_F(MeshTableIo, RefusesNonFiniteValues)
{
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
      MeshTable t = torque_table();
      t.values[t.values.size() / 2] = bad;
      const fs::path file = dir_ / "nan.h5";
      EXPECT_ANY_THROW(write_mesh_table(file, t, {"test", ""}));
      EXPECT_FALSE(fs::exists(file));
      EXPECT_TRUE(fs::is_empty(dir_)) << "temporary file left behind";
    }
}
