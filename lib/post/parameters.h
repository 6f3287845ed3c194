#pragma once
// ParameterHandler binding of the `Post` section: the thresholds of the per-position
// evaluation (post/position.h), with units and allowed ranges (docs/output-format.md).
#include "post/position.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::post
{
  void declare_post_parameters(dealii::ParameterHandler &prm);
  /// Read and check `Post`: InputError naming "Post/<entry>" for a value out of range.
  PostOptions parse_post_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::post
