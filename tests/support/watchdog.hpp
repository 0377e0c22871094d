// Runs a check in a child process (GoogleTest's death-test fork) under a watchdog alarm, for
// checks where a library bug could hang: the hang then fails the one test (killed by SIGALRM)
// instead of blocking the whole suite. The body returns "" on success or a description of what
// went wrong, which the child prints to stderr and GoogleTest shows with the failure.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace tactus::test {

template <typename Body>
[[noreturn]] void run_watched(unsigned seconds, Body&& body) {
    std::fputs("(a death by SIGALRM means the check did not finish: it hung)\n", stderr);
    ::alarm(seconds);
    const std::string failure = body();
    if (!failure.empty()) std::fputs(failure.c_str(), stderr);
    std::fflush(stderr);
    std::_Exit(failure.empty() ? 0 : 1);
}

}  // namespace tactus::test

// Expects `body` (a callable returning std::string) to finish within `seconds` and succeed.
#define TACTUS_EXPECT_FINISHES_OK(seconds, body) \
    EXPECT_EXIT(::tactus::test::run_watched(seconds, body), ::testing::ExitedWithCode(0), "")
