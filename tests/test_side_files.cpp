// Side files (io/side_files.h): only regular files are read, within their limit, without ever
// blocking; material libraries are told from other text; writes replace links instead of writing
// through them; the names beside OUT never land on the input's files or on files already there.
#include "side_files.h"

#include "errors.h"
#include "temp_dir_test.h"

#include <gtest/gtest.h>

#include <filesystem>

#include <sys/stat.h>

namespace fieldcvt {
namespace {

namespace fs = std::filesystem;

class SideFiles : public TempDirTest {};

TEST_F(SideFiles, OnlyRegularFilesWithinTheirLimitAreRead)
{
    const std::string file = write("a.mtl", "newmtl a\n");
    EXPECT_EQ(sideFileProblem(file, 100), "");
    EXPECT_EQ(readSideFile(file, 100), "newmtl a\n");
    EXPECT_NE(sideFileProblem(file, 4).find("limit"), std::string::npos);
    EXPECT_THROW(readSideFile(file, 4), IOError);
    EXPECT_EQ(sideFileProblem(path("missing.mtl"), 100), "does not exist");
    fs::create_directory(path("folder.mtl"));
    EXPECT_NE(sideFileProblem(path("folder.mtl"), 100).find("directory"), std::string::npos);
    EXPECT_THROW(readSideFile(path("folder.mtl"), 100), IOError);
    fs::create_symlink("/dev/zero", path("zero.mtl"));
    EXPECT_NE(sideFileProblem(path("zero.mtl"), 100).find("character device"), std::string::npos);
    EXPECT_THROW(readSideFile(path("zero.mtl"), 1u << 30), IOError);
    fs::create_symlink(file, path("link.mtl"));  // a link to a regular file is read as that file
    EXPECT_EQ(readSideFile(path("link.mtl"), 100), "newmtl a\n");
}

TEST_F(SideFiles, AFifoIsRefusedWithoutWaitingForAWriter)
{
    ASSERT_EQ(::mkfifo(path("pipe.png").c_str(), 0600), 0);
    EXPECT_NE(sideFileProblem(path("pipe.png"), 100).find("FIFO"), std::string::npos);
    try {
        readSideFile(path("pipe.png"), 100);  // would block forever in a plain open()
        FAIL() << "a FIFO was read";
    } catch (const IOError& e) {
        EXPECT_NE(std::string(e.what()).find("FIFO"), std::string::npos) << e.what();
    }
}

TEST_F(SideFiles, MaterialLibrariesAreToldFromOtherText)
{
    EXPECT_EQ(materialLibraryProblem("# Max2Mtl\nnewmtl a\nKa 1 1 1\n\tmap_Kd a.png\nillum 2\n"), "");
    EXPECT_EQ(materialLibraryProblem("newmtl a\nKd 1 1 1\nvendor_thing 3\nNs 10\nd 1\n"), "");  // one unknown of five
    EXPECT_NE(materialLibraryProblem("Private notes.\nThe password is swordfish.\n"), "");
    EXPECT_NE(materialLibraryProblem(""), "");
    EXPECT_NE(materialLibraryProblem("newmtl a\nThis is prose.\nMore prose here.\n"), "");
    EXPECT_NE(materialLibraryProblem(std::string("newmtl a\n\0\x01", 11)), "");
}

TEST_F(SideFiles, AWriteReplacesALinkAndNeverWritesThroughIt)
{
    const std::string victim = write("victim.png", "keep me");
    fs::create_symlink(victim, path("out.png"));
    writeFileReplacing(path("out.png"), "new bytes");
    EXPECT_EQ(bytes(victim), "keep me");
    EXPECT_FALSE(fs::is_symlink(path("out.png")));
    EXPECT_EQ(bytes(path("out.png")), "new bytes");
    // No temporary file is left, and a new file is not private (0666 less the umask).
    int files = 0;
    for (const auto& entry : fs::directory_iterator(path(""))) files += entry.path().filename().string()[0] == '.';
    EXPECT_EQ(files, 0);
    struct stat status {};
    ASSERT_EQ(::stat(path("out.png").c_str(), &status), 0);
    const mode_t mask = ::umask(0);
    ::umask(mask);
    EXPECT_EQ(status.st_mode & 0777, 0666 & ~mask);
}

TEST_F(SideFiles, AFailedWriteLeavesTheOldFileAndNoTemporary)
{
    const std::string old = write("out.stl", "old");
    EXPECT_THROW(writeFileReplacing(old, [](const std::string&) { throw IOError("exporter failed"); }), IOError);
    EXPECT_EQ(bytes(old), "old");
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(path(""))) ++entries;
    EXPECT_EQ(entries, 1);
}

TEST_F(SideFiles, NamesBesideTheOutputAvoidInputsExistingFilesAndEachOther)
{
    const std::string input = write("in.obj", "v 0 0 0\n");
    const std::string library = write("out.mtl", "newmtl a\n");
    write("out_texture.png", "someone's");
    fs::create_symlink(path("nowhere.png"), path("dangling.png"));
    std::vector<std::string> warnings;
    SideFileNames names(false);
    names.protect(input);
    names.protect(library);
    names.reserve(path("out.obj"));
    EXPECT_EQ(names.choose(path("out.mtl"), warnings), path("out_2.mtl"));  // the input's library
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("input's own files"), std::string::npos) << warnings[0];
    EXPECT_EQ(names.choose(path("out_texture.png"), warnings), path("out_texture_2.png"));  // exists
    EXPECT_NE(warnings.back().find("--overwrite"), std::string::npos) << warnings.back();
    EXPECT_EQ(names.choose(path("dangling.png"), warnings), path("dangling_2.png"));  // a dangling link exists too
    EXPECT_EQ(names.choose(path("new.png"), warnings), path("new.png"));
    EXPECT_EQ(names.choose(path("new.png"), warnings), path("new_2.png"));  // this run's own: not twice
    EXPECT_EQ(names.choose(path("out.obj"), warnings), path("out_2.obj"));  // the output itself
    EXPECT_EQ(warnings.size(), 5u);

    SideFileNames overwriting(true);
    overwriting.protect(input);
    overwriting.protect(library);
    std::vector<std::string> none;
    EXPECT_EQ(overwriting.choose(path("out_texture.png"), none), path("out_texture.png"));
    EXPECT_EQ(overwriting.choose(path("out.mtl"), none), path("out_2.mtl"));  // never the input's
    fs::create_symlink(input, path("link_to_input.obj"));
    EXPECT_EQ(overwriting.choose(path("link_to_input.obj"), none), path("link_to_input_2.obj"));
}

}  // namespace
}  // namespace fieldcvt
