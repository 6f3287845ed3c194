// `Post` section.
#include "post/parameters.h"

#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::post
{
  void declare_post_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    const PostOptions d;
    prm.enter_subsection("Post");
    prm.declare_entry("Min patch nodes", std::to_string(d.min_patch_nodes), Integer(),
                      "A loaded tooth pair with fewer slave nodes in contact has an unresolved "
                      "pressure patch: its peak pressure is flagged unresolved (column `resolved` "
                      "of pairs.csv) and no ellipse is fitted. Units: nodes. Allowed: >= 3.");
    prm.declare_entry("Loaded pair share", to_string_g(d.loaded_share), Double(),
                      "A tooth pair counts as loaded (column `pairs in contact` of sweep.csv) when its share "
                      "of the total normal load exceeds this. Units: none (fraction). "
                      "Allowed: [0, 1).");
    prm.declare_entry("Unresolved share", to_string_g(d.unresolved_share), Double(),
                      "Unresolved flank-to-flank pairs carrying a larger load share are counted in "
                      "the solve summary and warned about. Units: none (fraction). Allowed: [0, 1).");
    prm.declare_entry("Tip edge band", to_string_g(d.tip_edge_band), Double(),
                      "A contact node (or its master point) within this distance of the tip-form "
                      "circle of its gear is at the tip edge: the pair is edge contact (column "
                      "`edge contact`) and stays out of the Hertzian p_max. Units: module m_n. "
                      "Allowed: [0, 0.5].");
    prm.leave_subsection();
  }

  PostOptions parse_post_parameters(dealii::ParameterHandler &prm)
  {
    PostOptions o;
    prm.enter_subsection("Post");
    o.min_patch_nodes  = params::get_integer(prm, "Min patch nodes");
    o.loaded_share     = params::get_double(prm, "Loaded pair share");
    o.unresolved_share = params::get_double(prm, "Unresolved share");
    o.tip_edge_band    = params::get_double(prm, "Tip edge band");
    prm.leave_subsection();
    validate(o);
    return o;
  }
} // namespace gearfem::post
