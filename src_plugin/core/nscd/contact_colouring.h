// A colouring of the contact graph: contacts that share a body get different colours, so
// the contacts of one colour touch disjoint bodies and their Gauss–Seidel updates are
// independent (any order within a colour, or all at once, gives the same velocities).
// Swept colour by colour (SweepOrder::coloured, core/nscd/solver_settings.h), the sweep
// is the one a distributed solve would make with one exchange of the bodies' velocity
// changes per colour, the same on any decomposition (the variant (b) of docs/design.md
// section 3.4; measured there against the mass-splitting sweep).
//
// Greedy in the given order (the solver's top-down contact list): each contact takes the
// smallest colour that no earlier contact on either of its bodies took. A body of index
// < 0 (a wall, of infinite mass) couples nothing. With n_b the contacts on body b, the
// colours are at least max_b n_b (a body's contacts all differ) and at most
// 2 max_b n_b − 1 (a contact conflicts with at most n_a − 1 + n_b − 1 others).
#pragma once

#include <utility>
#include <vector>

namespace wiregrain {

struct ContactColouring {
  std::vector<int> colour;  // per contact
  std::vector<int> order;   // the contacts colour by colour, each colour in the given order
  int colours = 0;
};

// bodies[c] = (a, b) of contact c, −1 for a wall; body_count > every index.
ContactColouring colour_contacts(const std::vector<std::pair<int, int>>& bodies, int body_count);

}  // namespace wiregrain
