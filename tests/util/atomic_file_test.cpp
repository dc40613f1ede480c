// Atomic writes: a failed write leaves no file and no temporary file, an
// existing target survives a failed replacement, a bad folder is an
// InputError naming the path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/util/atomic_file.h"
#include "tests/support/files.h"
#include "tests/support/meshes.h"

namespace tsf {
namespace {

using test::listFiles;
using test::readText;
using test::scratchDir;
using test::writeText;
using ::testing::ElementsAre;
using ::testing::UnorderedElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

TEST(AtomicFile, SuccessfulWriteLeavesOnlyTheTarget) {
    const auto dir = scratchDir();
    const std::string target = (dir / "out.txt").string();
    writeFileAtomically(target, [](std::ostream& out) { out << "hello"; });
    EXPECT_EQ(readText(target), "hello");
    EXPECT_THAT(listFiles(dir), ElementsAre("out.txt"));
}

// The stamp a file gets as it is written is the one read back from it:
// small pieces gathered in the stamping buffer, a piece larger than that
// buffer passed straight through, and pieces on both sides of it.
TEST(OutputSet, TheStampTakenWhileWritingIsTheFilesStamp) {
    const auto dir = scratchDir();
    const std::string target = (dir / "model.stl").string(), other = (dir / "other.txt").string();
    std::string large(200000, '\0');
    for (size_t k = 0; k < large.size(); ++k) large[k] = char(k * 7919 % 251);
    OutputSet set;
    writeFileAtomically(target, [&](std::ostream& out) {
        out << "header " << 42 << ' ';
        out.put('x');
        out.write(large.data(), std::streamsize(large.size()));
        for (int k = 0; k < 5000; ++k) out << k << ',';
        out.write(large.data(), 1000);
    });
    AtomicFile plain(other);  // committed without a stamp: none to give
    writeText(plain.tempPath(), "bytes");
    plain.commit();
    const std::optional<FileStamp> taken = set.stampOf(target);
    ASSERT_TRUE(taken.has_value());
    const FileStamp read_back = stampFile(set.currentPath(target));
    EXPECT_EQ(*taken, read_back);
    EXPECT_GT(read_back.bytes, int64_t(201000));
    EXPECT_FALSE(set.stampOf(other).has_value());
    EXPECT_FALSE(set.stampOf((dir / "never.txt").string()).has_value());
    set.commit();
    EXPECT_EQ(stampFile(target), *taken);
}

TEST(OutputSet, AnEmptyFilesStampIsTheHashOfNothing) {
    const auto dir = scratchDir();
    const std::string target = (dir / "empty.txt").string();
    OutputSet set;
    writeFileAtomically(target, [](std::ostream&) {});
    const std::optional<FileStamp> taken = set.stampOf(target);
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->bytes, 0);
    EXPECT_EQ(taken->hash, 0x2d06800538d394c2ull);  // XXH3-64 of no bytes (the published vector)
    set.commit();
}

// A model made again in the same run is written again: the set keeps the
// newer file only, so its commit never renames the superseded one over the
// target, and no temporary file is left either way.
TEST(OutputSet, ATargetWrittenTwiceKeepsOnlyItsNewerFile) {
    const auto dir = scratchDir();
    const std::string target = (dir / "model.stl").string(), other = (dir / "key.txt").string();
    writeText(target, "old");
    {
        OutputSet set;
        writeFileAtomically(target, [](std::ostream& out) { out << "first"; });
        const std::string first_temp = set.currentPath(target);
        writeFileAtomically(other, [](std::ostream& out) { out << "key"; });
        writeFileAtomically(target, [](std::ostream& out) { out << "second"; });
        EXPECT_NE(set.currentPath(target), first_temp);
        EXPECT_EQ(readText(set.currentPath(target)), "second");
        EXPECT_EQ(set.stampOf(target)->bytes, 6);
        EXPECT_THAT(listFiles(dir), UnorderedElementsAre("model.stl", testing::StartsWith(".key.txt.tmp-"),
                                                         testing::StartsWith(".model.stl.tmp-")));
        EXPECT_EQ(readText(target), "old");
        set.commit();
    }
    EXPECT_EQ(readText(target), "second");
    EXPECT_EQ(readText(other), "key");
    EXPECT_THAT(listFiles(dir), UnorderedElementsAre("model.stl", "key.txt"));
}

TEST(OutputSet, AnUncommittedSetWrittenTwiceLeavesNothing) {
    const auto dir = scratchDir();
    const std::string target = (dir / "model.stl").string();
    {
        OutputSet set;
        writeFileAtomically(target, [](std::ostream& out) { out << "first"; });
        writeFileAtomically(target, [](std::ostream& out) { out << "second"; });
    }
    EXPECT_THAT(listFiles(dir), IsEmpty());
}

TEST(AtomicFile, TempFileIsInTheTargetFolderAndHidden) {
    const auto dir = scratchDir();
    AtomicFile file((dir / "model.stl").string());
    const std::filesystem::path temp(file.tempPath());
    EXPECT_EQ(temp.parent_path(), dir);
    EXPECT_EQ(temp.filename().string().rfind(".model.stl.tmp-", 0), 0u) << temp;
    EXPECT_TRUE(std::filesystem::exists(temp));
    EXPECT_FALSE(std::filesystem::exists(dir / "model.stl"));
}

TEST(AtomicFile, TwoWritersGetDifferentTempFiles) {
    const auto dir = scratchDir();
    AtomicFile a((dir / "x.off").string());
    AtomicFile b((dir / "x.off").string());
    EXPECT_NE(a.tempPath(), b.tempPath());
}

TEST(AtomicFile, WriterThatThrowsMidwayLeavesNoFileBehind) {
    const auto dir = scratchDir();
    const std::string target = (dir / "half.stl").string();
    EXPECT_THROW(writeFileAtomically(target,
                                     [](std::ostream& out) {
                                         out << std::string(100000, 'x');  // some data already written
                                         throw std::runtime_error("generator failed");
                                     }),
                 std::runtime_error);
    EXPECT_THAT(listFiles(dir), IsEmpty());
}

TEST(AtomicFile, ExistingTargetIsUntouchedWhenTheWriterFails) {
    const auto dir = scratchDir();
    const std::string target = (dir / "keep.obj").string();
    writeText(target, "old content");
    EXPECT_THROW(writeFileAtomically(target,
                                     [](std::ostream& out) {
                                         out << "new half";
                                         throw std::runtime_error("boom");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(readText(target), "old content");
    EXPECT_THAT(listFiles(dir), ElementsAre("keep.obj"));
}

TEST(AtomicFile, ExistingTargetIsReplacedOnSuccess) {
    const auto dir = scratchDir();
    const std::string target = (dir / "replace.txt").string();
    writeText(target, "a much longer old content than the new one");
    writeFileAtomically(target, [](std::ostream& out) { out << "new"; });
    EXPECT_EQ(readText(target), "new");
    EXPECT_THAT(listFiles(dir), ElementsAre("replace.txt"));
}

TEST(AtomicFile, UncommittedFileIsRemovedByTheDestructor) {
    const auto dir = scratchDir();
    std::string temp;
    {
        AtomicFile file((dir / "never.3mf").string());
        temp = file.tempPath();
        writeText(temp, "partial");
    }
    EXPECT_FALSE(std::filesystem::exists(temp));
    EXPECT_THAT(listFiles(dir), IsEmpty());
}

TEST(AtomicFile, CommitMovesTheTempFileOntoTheTarget) {
    const auto dir = scratchDir();
    const std::string target = (dir / "done.bin").string();
    AtomicFile file(target);
    writeText(file.tempPath(), "payload");
    file.commit();
    EXPECT_TRUE(file.committed());
    EXPECT_EQ(readText(target), "payload");
    EXPECT_FALSE(std::filesystem::exists(file.tempPath()));
}

TEST(AtomicFile, MissingFolderIsAnInputErrorNamingThePath) {
    const auto dir = scratchDir();
    const std::string target = (dir / "no-such-folder" / "out.stl").string();
    try {
        writeFileAtomically(target, [](std::ostream& out) { out << "x"; });
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), target);
        EXPECT_THAT(e.what(), HasSubstr("does not exist"));
        EXPECT_THAT(e.what(), HasSubstr("no-such-folder"));
    }
}

TEST(AtomicFile, TargetThatIsAFolderIsAnInputError) {
    const auto dir = scratchDir();
    std::filesystem::create_directory(dir / "sub.stl");
    EXPECT_THROW(AtomicFile((dir / "sub.stl").string()), InputError);
}

TEST(AtomicFile, UnwritableFolderIsAnInputError) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
    const auto dir = scratchDir();
    std::filesystem::create_directory(dir / "ro");
    std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    EXPECT_THROW(AtomicFile((dir / "ro" / "x.stl").string()), InputError);
    std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_all);
}

TEST(AtomicFile, MeshThatCannotBeWrittenLeavesTheOldFileAlone) {
    const auto dir = scratchDir();
    Mesh bad = test::cube();
    bad.positions[3].y = std::numeric_limits<double>::quiet_NaN();
    for (const char* name : {"a.stl", "a.3mf", "a.off", "a.obj"}) {
        const auto target = dir / name;
        writeText(target, "previous");
        EXPECT_THROW(writeMesh(bad, target.string()), InputError) << name;
        EXPECT_EQ(readText(target), "previous") << name;
    }
    EXPECT_EQ(listFiles(dir).size(), 4u);
}

// The pid of a process that has ended (a child, reaped).
pid_t endedPid() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
}

TEST(StaleTempFiles, OnlyThisTargetsFilesOfEndedProcessesAreRemoved) {
    const auto dir = scratchDir();
    const std::string dead = std::to_string(endedPid()), live = std::to_string(::getppid());
    for (const std::string& name : std::vector<std::string>{
             ".m.stl.tmp-" + dead + "-0", "..m.stl.tmp-" + dead + "-3.tmp-" + dead + "-4", ".m.stl.tmp-" + live + "-0",
          ".other.stl.tmp-" + dead + "-0", "m.stl.tmp-" + dead + "-0", ".m.stl.tmp-" + dead, ".m.stl.tmp-x-1",
          std::string("m.stl")})
        writeText(dir / name, "x");
    EXPECT_EQ(removeStaleTempFiles((dir / "m.stl").string()), 2);
    EXPECT_THAT(listFiles(dir),
                UnorderedElementsAre(".m.stl.tmp-" + live + "-0", ".other.stl.tmp-" + dead + "-0",
                                     "m.stl.tmp-" + dead + "-0", ".m.stl.tmp-" + dead, ".m.stl.tmp-x-1", "m.stl"));
    // A new AtomicFile for the target does the same on its way.
    writeText(dir / (".m.stl.tmp-" + dead + "-7"), "x");
    AtomicFile file((dir / "m.stl").string());
    EXPECT_FALSE(std::filesystem::exists(dir / (".m.stl.tmp-" + dead + "-7")));
}

}  // namespace
}  // namespace tsf
