#pragma once
// The in-memory mesh table: T(theta, delta), k(theta, F) or STE(theta, T) on two axes, as
// the calibration writes it and the dynamics reads it. The file layout is in
// io/mesh_table_io.h and docs/mesh-tables.md; the table type lives here, below both the
// calibration and the dynamics (data flows one way: io does not include dynamics).
#include <string>
#include <vector>

namespace gearfem::io
{
  /// A mesh table on in-memory axes, as the calibration work writes it (HDF5: io/mesh_table_io.h).
  /// Either the pinion torque T(theta, delta) or the mesh stiffness k(theta, F).
  struct MeshTable
  {
    enum class Kind
    {
      torque_vs_compression, ///< values: T [N*m] on (theta [rad], delta [m])
      stiffness_vs_load,     ///< values: k [N/m] on (theta [rad], F [N])
      ste_vs_torque          ///< values: STE [m] on (theta [rad], T [N*m]) (not a force law)
    };
    Kind kind = Kind::torque_vs_compression;
    std::vector<double> theta;  ///< strictly increasing, within one mesh period [rad]
    /// delta [m], F [N] or T [N*m], strictly increasing, >= 0; a two-sided torque table
    /// (backlash >= 0) starts below -backlash.
    std::vector<double> second;
    std::vector<double> values; ///< row-major: values[i * second.size() + j]
    double period = 0;          ///< mesh period in theta [rad] (table is periodic in theta)
    std::string theta_unit = "rad", second_unit = "m", value_unit = "N*m";
    std::string geometry_hash;  ///< hash of the GearPair the table was computed for
    double base_radius = 0;     ///< pinion base radius r_b1 [m] (T = F r_b1)
    /// Two-sided torque tables only: the clearance b >= 0 along the line of action [m]. The
    /// delta axis then runs from below -b to above 0 and has nodes at -b and 0; T = 0 on
    /// [-b, 0] (loss of contact) and T <= 0 below -b (the reverse flank, delta_r = -delta - b).
    /// < 0: a one-sided table (delta >= 0, the drive flank only).
    double backlash = -1;
    bool two_sided() const { return kind == Kind::torque_vs_compression && backlash >= 0; }
    /// Throws InputError for missing axes, wrong units, inconsistent sizes, non-monotone
    /// axes, and (if expected_hash is not empty) a geometry hash mismatch.
    void check(const std::string &expected_hash = "") const;
    /// Throws InputError if the load F [N] (static mesh force) is not inside the table.
    void require_covers_load(double F) const;
    double value(std::size_t i, std::size_t j) const { return values[i * second.size() + j]; }
  };

  /// Name and unit of the second axis ("delta" m, "load" N, "torque" N*m), the unit of the
  /// values ("N*m", "N/m", "m") and their quantity ("torque", "stiffness", "transmission
  /// error") of a table kind: the names of docs/mesh-tables.md, shared by the writer, the reader and the dynamics.
  const char *second_axis_name(MeshTable::Kind k);
  const char *second_axis_unit(MeshTable::Kind k);
  const char *value_axis_unit(MeshTable::Kind k);
  const char *value_quantity(MeshTable::Kind k);
  /// The delta axis of a torque table from its drive-side compressions `drive` (ascending,
  /// from 0): `drive` itself when one-sided (backlash < 0), else the reverse side
  /// -b - drive (descending), a node at 0 when b > 0, then the drive side.
  std::vector<double> torque_table_axis(const std::vector<double> &drive, double backlash);
  /// Index of the node of `axis` at x (relative tolerance 1e-9 of the axis span); -1: none.
  long node_at(const std::vector<double> &axis, double x);
} // namespace gearfem::io
