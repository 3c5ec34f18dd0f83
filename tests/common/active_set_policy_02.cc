/*
 * The third state of a frictional node (ActiveSetPolicy::update(), on
 * plain node data): a node open at the start of the step penetrates its
 * partner and closes slipping (its slip increment is not zero); closed and
 * slipping, it pulls (negative pressure), and the rule would open it
 * again, a set the step has seen. With Coulomb friction the update then
 * tries the state between the two, stick, which the step has not seen:
 * the node sticks and the update is no cycle. A later pull proposes the
 * open set again, seen, and the node already sticks: the update reports a
 * cycle and leaves the set unchanged. Without
 * friction a closed node only slips, and the same sequence is a cycle at
 * once.
 */

#include <common/contact/active_set_policy.h>
#include <common/contact/contact_state.h>
#include <common/contact/free_directions.h>
#include <common/contact/friction_model.h>
#include <common/contact/normal_enforcement.h>

#include "../tests.h"

#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

using namespace dealii;
using namespace Common::Contact;

namespace
{
  std::string
  name(const PointStatus status)
  {
    return status == PointStatus::open  ? "open" :
           status == PointStatus::stick ? "stick" :
                                          "slip";
  }



  void
  run(const FrictionModel<2> &friction, const std::string &label)
  {
    deallog << label << std::endl;
    ContactParameters parameters;
    parameters.ncp_factor            = 1.;
    parameters.tangential_ncp_factor = 1.;
    parameters.accelerate_release    = false;

    Tensor<1, 2> normal_direction;
    normal_direction[1] = 1.;
    const FreeDirections<2> directions(
      std::vector<Tensor<1, 2>>{normal_direction});
    ContactState<2> state(directions);
    state.reset({PointStatus::open});

    std::vector<NodeKinematics<2>> nodes(1);
    nodes[0].paired    = true;
    nodes[0].weight    = 1.;
    nodes[0].mesh_size = 1.;
    nodes[0].nodal_gap = 0.;
    // Penetrating by 4e-3 mm, moved along the tangent by 0.1 mm in the
    // step.
    nodes[0].weighted_gap             = -4e-3;
    nodes[0].relative_displacement[0] = 0.1;

    ActiveSetPolicy<2>         policy(parameters, 1.);
    DualLagrangeEnforcement<2> normal;
    policy.begin_step(state);

    const auto report = [&](const std::string &what, const unsigned int n) {
      deallog << "  " << what << ": " << name(state.node(0).status) << ", " << n
              << " changed, cycling " << policy.is_cycling() << std::endl;
    };

    report("penetrating", policy.update(nodes, normal, friction, state));

    // Closed: at the partner, pulling on it.
    nodes[0].weighted_gap                = 0.;
    state.node(0).pressure               = -0.6;
    state.node(0).tangential_traction[0] = (friction.has_friction() ? -3. : 0.);
    report("pulling", policy.update(nodes, normal, friction, state, -1., true));

    report("pulling again",
           policy.update(nodes, normal, friction, state, -1., true));
  }
} // namespace



int
main()
{
  initlog();
  run(CoulombFriction<2>(5.), "Coulomb friction, mu = 5");
  run(Frictionless<2>(), "frictionless");
}
