// The library routines for V = double (the scalar interpreter).
#include "frep/kernels/library/library_impl.h"

namespace hg::frep::lib {

template double call<double>(int, const Args<double>&);

}  // namespace hg::frep::lib
