// Runs the `hypergarden` executable as a user would, in a scratch
// directory, for the command-line tests of every module. Tests skip when
// the executable is not built (the sanitizer preset builds no app).
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace hg::test {

struct CommandRun {
    int status = -1;
    std::string output;  // stdout and stderr together
};

// `environment`: assignments for the command ("NAME=value ...").
inline CommandRun runHypergarden(const std::string& args, const std::string& environment = "") {
    CommandRun r;
#ifdef HG_HYPERGARDEN_EXE
    std::string cmd = environment + (environment.empty() ? "" : " ") + "'" + HG_HYPERGARDEN_EXE + "' " + args + " 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    int st = ::pclose(pipe);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
#else
    (void)args;
    (void)environment;
#endif
    return r;
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
#ifndef HG_HYPERGARDEN_EXE
        GTEST_SKIP() << "the hypergarden executable is not built (HG_BUILD_APP=OFF)";
#endif
        dir = std::filesystem::temp_directory_path() /
              ("hg_cli_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir);
    }
    void TearDown() override {
        if (!dir.empty()) std::filesystem::remove_all(dir);
    }
    // A quoted path in the scratch directory, for command lines.
    std::string path(const std::string& name) const { return "'" + (dir / name).string() + "'"; }
    bool exists(const std::string& name) const { return std::filesystem::exists(dir / name); }
    std::size_t entries() const {
        return static_cast<std::size_t>(
            std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
    }
    std::filesystem::path dir;
};

}  // namespace hg::test
