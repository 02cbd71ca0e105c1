#include "io/write_faults.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <mutex>

#include <unistd.h>

namespace hg::io {

namespace {

constexpr std::array<const char*, static_cast<std::size_t>(WriteSite::Count)> kSiteNames = {
    "journal", "snapshot-grid", "snapshot-manifest", "session-file", "settings", "export", "screenshot", "stats", "page-file"};

struct Seam {
    std::mutex mutex;
    std::optional<FaultPlan> plan;
    std::array<std::size_t, static_cast<std::size_t>(WriteSite::Count)> steps{};
    std::size_t anySteps = 0;
};

Seam& seam() {
    static Seam s;
    return s;
}

std::atomic<int> gState{-1};  // -1: HG_FAIL_WRITE not read yet; 0: no plan; 1: a plan

void readEnvironmentOnce() {
    if (gState.load(std::memory_order_acquire) >= 0) return;
    std::lock_guard<std::mutex> lock(seam().mutex);
    if (gState.load(std::memory_order_relaxed) >= 0) return;
    const char* env = std::getenv("HG_FAIL_WRITE");
    if (env && *env) {
        std::string why;
        seam().plan = parseFaultPlan(env, why);
        // A test that asked for a fault must not pass because it was misspelt.
        if (!seam().plan) {
            std::cerr << "error: HG_FAIL_WRITE: " << why << "\n";
            std::_Exit(2);
        }
    }
    gState.store(seam().plan ? 1 : 0, std::memory_order_release);
}

bool parseCount(const std::string& s, std::size_t& out) {
    if (s.empty() || s.size() > 12) return false;
    std::size_t v = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + static_cast<std::size_t>(c - '0');
    }
    out = v;
    return v > 0;
}

}  // namespace

const char* writeSiteName(WriteSite site) { return kSiteNames[static_cast<std::size_t>(site)]; }

std::optional<FaultPlan> parseFaultPlan(const std::string& text, std::string& why) {
    FaultPlan plan;
    std::string rest = text;
    const std::size_t lastColon = rest.rfind(':');
    if (lastColon == std::string::npos) {
        why = "expected [SITE:]N[-[M]]:ERROR, got '" + text + "'";
        return std::nullopt;
    }
    const std::string error = rest.substr(lastColon + 1);
    rest = rest.substr(0, lastColon);
    if (error == "ENOSPC") plan.error = ENOSPC;
    else if (error == "EIO") plan.error = EIO;
    else if (error == "EDQUOT") plan.error = EDQUOT;
    else if (error == "EROFS") plan.error = EROFS;
    else if (error == "EFBIG") plan.error = EFBIG;
    else if (error == "KILL") plan.kill = true;
    else {
        why = "unknown error '" + error + "' (expected ENOSPC, EIO, EDQUOT, EROFS, EFBIG or KILL)";
        return std::nullopt;
    }
    if (const std::size_t colon = rest.find(':'); colon != std::string::npos) {
        const std::string site = rest.substr(0, colon);
        rest = rest.substr(colon + 1);
        bool found = false;
        for (std::size_t i = 0; i < kSiteNames.size(); ++i)
            if (site == kSiteNames[i]) {
                plan.anySite = false;
                plan.site = static_cast<WriteSite>(i);
                found = true;
            }
        if (!found) {
            why = "unknown write site '" + site + "' (expected journal, snapshot-grid, snapshot-manifest, session-file, "
                  "settings, export, screenshot, stats or page-file)";
            return std::nullopt;
        }
    }
    const std::size_t dash = rest.find('-');
    const bool ok = dash == std::string::npos
                        ? parseCount(rest, plan.first) && (plan.last = plan.first, true)
                        : parseCount(rest.substr(0, dash), plan.first) &&
                              (dash + 1 == rest.size() ? (plan.last = SIZE_MAX, true)
                                                       : parseCount(rest.substr(dash + 1), plan.last) && plan.last >= plan.first);
    if (!ok) {
        why = "expected a step number N, a range N-M or N- (from 1), got '" + rest + "'";
        return std::nullopt;
    }
    return plan;
}

void setFaultPlan(std::optional<FaultPlan> plan) {
    readEnvironmentOnce();
    std::lock_guard<std::mutex> lock(seam().mutex);
    seam().plan = plan;
    seam().steps.fill(0);
    seam().anySteps = 0;
    gState.store(plan ? 1 : 0, std::memory_order_release);
}

int injectedFailure(WriteSite site) {
    readEnvironmentOnce();
    if (gState.load(std::memory_order_acquire) == 0) return 0;
    std::lock_guard<std::mutex> lock(seam().mutex);
    if (!seam().plan) return 0;
    const FaultPlan& p = *seam().plan;
    const std::size_t siteStep = ++seam().steps[static_cast<std::size_t>(site)];
    const std::size_t anyStep = ++seam().anySteps;
    const std::size_t step = p.anySite ? anyStep : siteStep;
    if ((!p.anySite && p.site != site) || step < p.first || step > p.last) return 0;
    if (p.kill) ::kill(::getpid(), SIGKILL);
    return p.error;
}

}  // namespace hg::io
