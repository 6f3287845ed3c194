#pragma once
// Output helpers of the fem module (the VTU writer itself is ElasticBody::write_vtu).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <typename> class Vector;
}

namespace gearfem::fem
{
  class ElasticBody;

  /// A body placed rigidly in a common frame: x = centre + R(angle) (X + scale u(X)).
  struct PlacedBody
  {
    const ElasticBody *body = nullptr;
    const dealii::Vector<double> *u = nullptr;        ///< body-frame displacement [m]
    const dealii::Vector<double> *traction = nullptr; ///< optional nodal contact traction, body frame [Pa]
    double angle = 0;                                 ///< [rad]
    double centre[2] = {0, 0};                        ///< [m]
  };

  /// Write several placed bodies into one VTU (atomically): displacement [mm], contact
  /// traction [MPa] and the stress components [MPa], all rotated into the common frame,
  /// plus sigma_1, sigma_2, von Mises and the boundary ids.
  void write_placed_vtu(const std::vector<PlacedBody> &bodies, const std::filesystem::path &file,
                        double scale = 1.0);

  /// Write a ParaView .pvd collection of (time or position, vtu file name) records, atomically.
  void write_pvd(const std::filesystem::path &file,
                 const std::vector<std::pair<double, std::string>> &records);
} // namespace gearfem::fem
