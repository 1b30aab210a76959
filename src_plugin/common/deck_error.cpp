#include "deck_error.h"

#include <string>

#include "error.h"

using namespace LAMMPS_NS;

void DeckError::command(int narg, char **arg) {
  std::string what;
  for (int k = 0; k < narg; k++) what += (k ? " " : "") + std::string(arg[k]);
  if (what.empty()) what = "deck_error: the deck stopped (no message given)";
  error->all(FLERR, what.c_str());
}
