// A fault plan for the write seam (io/write_faults.h): every write step at
// one site fails as on a full disk, from the first on.
#pragma once

#include <cerrno>
#include <cstdint>

#include "io/write_faults.h"

namespace hg::test {

inline io::FaultPlan diskFullAt(io::WriteSite site) {
    io::FaultPlan full;
    full.anySite = false;
    full.site = site;
    full.first = 1;
    full.last = SIZE_MAX;
    full.error = ENOSPC;
    return full;
}

}  // namespace hg::test
