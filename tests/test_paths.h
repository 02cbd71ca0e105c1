// Where the tests and benches find the source tree, its test data and the
// programs they run. The paths are compiled into one file, test_paths.cpp,
// and the build has every source of a test or bench target read this
// header first (CMake's hg_test_paths): no other compile line names the
// folder the tree sits in, so those objects are the same in any clone and a
// compiler cache serves them there (.ci/run sets CCACHE_BASEDIR; README,
// "Set up").
#pragma once

namespace hg::test {

const char* sourceDir();       // the source tree's root
const char* testDataDir();     // tests/data
const char* hypergardenExe();  // the built program ("" where it is not built)
const char* mockXrManifest();  // the mock OpenXR runtime's manifest ("" where XR is not built)
const char* mockXrLibrary();   // the mock OpenXR runtime itself ("" where XR is not built)

}  // namespace hg::test

#define HG_SOURCE_DIR (::hg::test::sourceDir())
#define HG_TEST_DATA_DIR (::hg::test::testDataDir())
#ifdef HG_HAS_HYPERGARDEN_EXE
#define HG_HYPERGARDEN_EXE (::hg::test::hypergardenExe())
#endif
#ifdef HG_HAS_MOCK_XR_MANIFEST
#define HG_MOCK_XR_MANIFEST (::hg::test::mockXrManifest())
#define HG_MOCK_XR_LIBRARY (::hg::test::mockXrLibrary())
#endif
