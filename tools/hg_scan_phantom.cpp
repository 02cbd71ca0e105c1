// Writes the synthetic scanned head (tools/scan_phantom.h) as raw u8
// samples: `hg_scan_phantom content/volumes/phantom.raw` rebuilds the
// committed file (a test checks they agree).
#include <cstdio>
#include <fstream>

#include "tools/scan_phantom.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: hg_scan_phantom OUT.raw\n");
        return 2;
    }
    const std::vector<std::uint8_t> samples = hg::tools::makePhantom();
    std::ofstream out(argv[1], std::ios::binary);
    out.write(reinterpret_cast<const char*>(samples.data()), static_cast<std::streamsize>(samples.size()));
    out.close();
    if (!out) {
        std::fprintf(stderr, "error: cannot write %s\n", argv[1]);
        return 1;
    }
    std::printf("wrote %s: %d^3 u8 samples, spacing %g\n", argv[1], hg::tools::kPhantomSize, hg::tools::kPhantomSpacing);
    return 0;
}
