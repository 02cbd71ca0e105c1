// The library routines instantiated on Sym: the compiler records each
// routine's operations onto the tape (see frep/library/library.h).
#include "frep/library/library_impl.h"
#include "frep/sym.h"

namespace hg::frep::lib {
template Sym call<Sym>(int, const Args<Sym>&);
}  // namespace hg::frep::lib
