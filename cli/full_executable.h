// `hypergarden` runs check and eval itself and hands every other command to
// `hypergarden-full`, built next to it from the same main.cpp with
// everything linked in.
//
// Why two executables: loading OpenVDB costs about 40 ms before main()
// (libopenvdb is linked with BIND_NOW, so the loader resolves its tens of
// thousands of symbols, and log4cplus starts threads), which was almost all
// of eval's start-up (the reference interpreter starts in 1 to 4 ms). The
// kernel-only executable links no OpenVDB, TBB or GL.
#pragma once

namespace hg::garden::cli {

// Replaces this process with hypergarden-full from this executable's folder,
// given the same arguments. Returns (an exit status, after saying why) only
// when that cannot be started.
int runFullExecutable(char** argv);

}  // namespace hg::garden::cli
