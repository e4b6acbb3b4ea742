// How many OpenMP threads a run takes (core/thread_budget.h): one per core no other task holds,
// decided in-process for the CLI and the MeshLab filter alike (issue 38).
#include "remesh.h"
#include "test_meshes.h"
#include "thread_budget.h"

#include <gtest/gtest.h>

#include <omp.h>

using namespace fieldcvt;

TEST(ThreadBudget, OtherRunnableTasksFromLoadavg)
{
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 1/80 12345\n"), 0);  // only the reader runs
    EXPECT_EQ(otherRunnableTasks("2.00 1.21 1.16 3/79 13827"), 2);
    EXPECT_EQ(otherRunnableTasks(""), -1);
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30"), -1);
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 80 1"), -1);    // no slash
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 /80 1"), -1);   // no count
    EXPECT_EQ(otherRunnableTasks("0.10 0.20 0.30 0/80 1"), -1);  // the reader itself is missing
    EXPECT_EQ(otherRunnableTasks("a b c 1/2 3"), -1);
}

TEST(ThreadBudget, OneThreadPerFreeCoreUnlessAsked)
{
    EXPECT_EQ(threadsForLoad(0, 2, 0), 2);  // an idle machine: every core
    EXPECT_EQ(threadsForLoad(0, 2, 1), 1);  // a busy process beside: the other core
    EXPECT_EQ(threadsForLoad(0, 2, 5), 1);  // all taken: still one
    EXPECT_EQ(threadsForLoad(0, 8, 3), 5);
    EXPECT_EQ(threadsForLoad(0, 4, -1), 4);  // load unknown: every core
    EXPECT_EQ(threadsForLoad(3, 2, 1), 3);   // asked for: as asked (the output is the same)
    EXPECT_EQ(threadsForLoad(0, 0, 0), 1);
}

TEST(ThreadBudget, RemeshTakesItsCountAndRestoresTheCallers)
{
    // The host's (MeshLab's) setting survives the run, whatever the run took.
    omp_set_num_threads(3);
    RemeshParams p;
    p.vertexCount = 200;
    p.threads = 2;
    const RemeshResult asked = remesh(testmesh::icosphere(2), p);
    EXPECT_EQ(asked.threads, 2);
    EXPECT_EQ(omp_get_max_threads(), 3);
    p.threads = 0;
    const RemeshResult automatic = remesh(testmesh::icosphere(2), p);
    EXPECT_GE(automatic.threads, 1);
    EXPECT_EQ(omp_get_max_threads(), 3);
    EXPECT_EQ(asked.mesh.vertices, automatic.mesh.vertices);  // the same output on any count
}
