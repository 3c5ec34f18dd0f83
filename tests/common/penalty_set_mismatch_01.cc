// Checks Common::Contact::PenaltyEnforcement::complementarity(), the
// departure of a node's force from the penalty law p = k max(0, -g) that
// measures how far a penalty's active set is from the law. With the
// pressures that update_tractions() gives (-k g on a closed node, 0 on an
// open one), it must be -k g on a closed node with a positive gap (its
// spring pulls), k g on an open node that penetrates, and exactly 0 on a
// closed node that penetrates or touches and on an open node with a
// non-negative gap, whatever the complementarity constant c; is_closed()
// must agree with the sign of the gap (touching closes). A node whose
// status agrees with is_closed() has no departure; an open node that
// touches (g = 0) disagrees with is_closed() but carries the law's force,
// none, so it has no departure either.

#include <common/contact/normal_enforcement.h>

#include "../tests.h"

#include <vector>

using namespace dealii;

int
main()
{
  initlog();
  const double                           k = 1e4;
  Common::Contact::PenaltyEnforcement<2> penalty(k);
  struct Case
  {
    const char *name;
    bool        closed;
    double      g;
  };
  const std::vector<Case> cases = {{"closed, g < 0", true, -1e-3},
                                   {"closed, g = 0", true, 0.},
                                   {"closed, g > 0", true, 2e-3},
                                   {"open,   g < 0", false, -1e-3},
                                   {"open,   g = 0", false, 0.},
                                   {"open,   g > 0", false, 2e-3}};
  for (const double c : {1., 1e3, 1e6})
    for (const Case &node : cases)
      {
        const double p        = node.closed ? -k * node.g : 0.;
        const double C        = penalty.complementarity(p, node.g, c);
        const bool   agrees   = penalty.is_closed(p, node.g, c) == node.closed;
        double       expected = 0.;
        if (node.closed && node.g > 0.)
          expected = -k * node.g;
        if (!node.closed && node.g < 0.)
          expected = k * node.g;
        deallog << "c = " << c << ", " << node.name << ": departure " << C
                << " MPa, set agrees with the law " << agrees << ", "
                << (C == expected && (!agrees || C == 0.) ? "ok" : "WRONG")
                << std::endl;
      }
}
