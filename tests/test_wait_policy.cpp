// The CLI's choice of how idle OpenMP threads wait (cli/wait_policy.h): spin while every thread
// has a core of its own, sleep at once when other runnable tasks would share them.
#include "wait_policy.h"

#include <gtest/gtest.h>

using namespace fieldcvt::cli;

TEST(WaitPolicy, OtherRunnableTasksFromLoadavg)
{
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 1/80 12345\n"), 0);  // only the reader runs
    EXPECT_EQ(otherRunnableTasks("2.00 1.21 1.16 3/79 13827"), 2);
    EXPECT_EQ(otherRunnableTasks(""), -1);
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30"), -1);
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 80 1"), -1);   // no slash
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 /80 1"), -1);  // no count
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 0/80 1"), -1);  // the reader itself is missing
    EXPECT_EQ(otherRunnableTasks("a b c 1/2 3"), -1);
}

TEST(WaitPolicy, SpinsOnlyWithACorePerThread)
{
    EXPECT_TRUE(spinningFits(0, 2, 2));
    EXPECT_FALSE(spinningFits(1, 2, 2));   // a busy process beside two threads on two cores
    EXPECT_TRUE(spinningFits(1, 2, 4));
    EXPECT_FALSE(spinningFits(3, 2, 4));
    EXPECT_FALSE(spinningFits(-1, 1, 8));  // load unknown: sleep
    EXPECT_FALSE(spinningFits(0, 0, 2));
    EXPECT_FALSE(spinningFits(0, 2, 0));
}

TEST(WaitPolicy, RequestedThreadsFromTheCommandLine)
{
    char prog[] = "fcvt", remesh[] = "remesh", threads[] = "--threads", one[] = "1", zero[] = "0";
    char* withOne[] = {prog, remesh, threads, one, nullptr};
    char* withZero[] = {prog, remesh, threads, zero, nullptr};
    char* without[] = {prog, remesh, nullptr};
    char* dangling[] = {prog, threads, nullptr};
    EXPECT_EQ(requestedThreads(4, withOne, 8), 1);
    EXPECT_EQ(requestedThreads(4, withZero, 8), 8);  // 0: one per core
    EXPECT_EQ(requestedThreads(2, without, 8), 8);
    EXPECT_EQ(requestedThreads(2, dangling, 8), 8);
}
