// A folder of the running test's own under the temporary folder (its name
// carries the process and the test, so tests running side by side never
// share one), emptied when made and removed when it goes.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

namespace hg::test {

struct TestFolder {
    std::filesystem::path path;
    // `make` false: named and emptied, not made (for what makes it itself).
    explicit TestFolder(const std::string& prefix, bool make = true) {
        path = std::filesystem::temp_directory_path() /
               (prefix + "_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(path);
        if (make) std::filesystem::create_directories(path);
    }
    ~TestFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TestFolder(const TestFolder&) = delete;
    TestFolder& operator=(const TestFolder&) = delete;
    std::string file(const std::string& name) const { return (path / name).string(); }
    std::size_t entries() const {
        return static_cast<std::size_t>(
            std::distance(std::filesystem::directory_iterator(path), std::filesystem::directory_iterator()));
    }
};

}  // namespace hg::test
