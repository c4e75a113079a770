#include "symcontact/optim/ordering_seed.hpp"

#include <cstdlib>

#include <scotch.h>

namespace symcontact {

void restart_ordering_sequence() {
  // SCOTCH 7 reads the number of threads when it orders (the plates differed with the sequence restarted
  // alone, even on one core).
  setenv("SCOTCH_PTHREAD_NUMBER", "1", 1);
  SCOTCH_randomSeed(1);
  SCOTCH_randomReset();
}

}  // namespace symcontact
