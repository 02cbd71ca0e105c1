// The one file compiled with the trees' paths (tests/test_paths.h).
#include "tests/test_paths.h"

namespace hg::test {

const char* sourceDir() { return HG_PATH_SOURCE_DIR; }
const char* testDataDir() { return HG_PATH_SOURCE_DIR "/tests/data"; }
const char* hypergardenExe() { return HG_PATH_HYPERGARDEN_EXE; }
const char* mockXrManifest() { return HG_PATH_MOCK_XR_MANIFEST; }
const char* mockXrLibrary() { return HG_PATH_MOCK_XR_LIBRARY; }

}  // namespace hg::test
