/* deck_error: stop a deck with an ERROR naming what is wrong, for the checks a deck makes
   of its own variables (LIGGGHTS 3.8's `quit` takes no message and exits with status 0).

   deck_error word ...      e.g.  if "${R} <= 0" then "deck_error in.column: R must be > 0, got ${R}"

   stops the run through error->all: rank 0 prints "ERROR: <the words> (<source>:<line>)" to
   the screen and the log file, and every rank exits with status 1. No words: the message is
   "deck_error: the deck stopped (no message given)". */

#ifdef COMMAND_CLASS

CommandStyle(deck_error,DeckError)

#else

#ifndef LMP_DECK_ERROR_H
#define LMP_DECK_ERROR_H

#include "pointers.h"

namespace LAMMPS_NS {

class DeckError : protected Pointers {
 public:
  DeckError(class LAMMPS *lmp) : Pointers(lmp) {}
  void command(int, char **);
};

}  // namespace LAMMPS_NS

#endif
#endif
