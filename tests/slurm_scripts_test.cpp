// The Slurm side of sweeps without Slurm: the words and quotes of options, running a program,
// the array syntax, and the batch scripts of `--slurm --dry-run` run by hand (as Slurm would,
// with SLURM_ARRAY_TASK_ID set), which must merge into the table of a local run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "cluster/process.hpp"
#include "cluster/slurm_scripts.hpp"
#include "penumbra_process.hpp"
#include "sweep_scenes.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::runPenumbra;
using testing::TempDir;

TEST(SlurmScripts, ArraysAreWrittenInSlurmsRangeSyntax) {
  EXPECT_EQ(arraySpec({1, 2, 3, 4}), "1-4");
  EXPECT_EQ(arraySpec({2}), "2");
  EXPECT_EQ(arraySpec({1, 2, 3, 5, 7, 8}), "1-3,5,7-8");
  EXPECT_EQ(arraySpec({}), "");
}

TEST(SlurmScripts, OptionsSplitIntoWordsAsAShellWould) {
  const std::string text = R"(--partition=compute  --time=00:30:00 --comment='a b' -J "x y"z)";
  const std::vector<std::string> words = splitShellWords(text);
  // The shell's own split of the same text, one word a line.
  const ProcessResult shell = runProcess({"sh", "-c", "printf '%s\\n' " + text});
  ASSERT_EQ(shell.status, 0) << shell.err;
  EXPECT_EQ(words, testing::lines(shell.out));
  EXPECT_EQ(words.size(), 5u);
  EXPECT_THROW(splitShellWords("--comment='open"), std::invalid_argument);
  EXPECT_TRUE(splitShellWords("  ").empty());
}

TEST(SlurmScripts, QuotedWordsReachAProgramUnchanged) {
  for (const std::string word : {"plain", "with space", "it's", "$HOME `x` \"q\" \\ *", ""}) {
    const ProcessResult r = runProcess({"sh", "-c", "printf '%s' " + shellQuote(word)});
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, word);
  }
}

TEST(SlurmScripts, RunProcessKeepsOutputErrorAndStatusApart) {
  const ProcessResult r = runProcess({"sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.out, "out\n");
  EXPECT_EQ(r.err, "err\n");
  // More than a pipe holds, on both streams at once: neither may block the other.
  const ProcessResult big =
      runProcess({"sh", "-c", "head -c 300000 /dev/zero; head -c 200000 /dev/zero >&2"});
  EXPECT_EQ(big.out.size(), 300000u);
  EXPECT_EQ(big.err.size(), 200000u);
  EXPECT_THROW(runProcess({"penumbra-no-such-program"}), std::runtime_error);
}

constexpr const char* kStudy = R"(penumbra-study: 1
scene: scene.yaml
parameters:
  flux: [1000, 2000, 3000]
  y: [1, 2]
charts: false
)";

using testing::kParameterisedRoom;

class SlurmDryRun : public ::testing::Test {
 protected:
  SlurmDryRun() : dir_("penumbra-slurm-dry") {
    std::ofstream(dir_.path() / "study.yaml") << kStudy;
    std::ofstream(dir_.path() / "scene.yaml") << kParameterisedRoom;
  }
  TempDir dir_;
};

TEST_F(SlurmDryRun, WritesScriptsThatDoTheStudyWhenRunAsSlurmWould) {
  const testing::Result dry = runPenumbra(
      dir_.path(),
      "sweep study.yaml -o out --slurm --shards 3 --dry-run --slurm-opt \"--time=00:10:00 "
      "--comment='a b'\" --device cpu");
  ASSERT_EQ(dry.status, 0) << dry.err;
  const fs::path slurm = dir_.path() / "out" / "slurm";
  const std::string shardScript = readText(slurm / "sweep.sbatch");
  EXPECT_NE(shardScript.find("#SBATCH --array=1-3\n"), std::string::npos) << shardScript;
  EXPECT_NE(shardScript.find("--shard \"${shard}/3\""), std::string::npos) << shardScript;
  EXPECT_NE(dry.out.find("sbatch --parsable --time=00:10:00 '--comment=a b' " +
                         (slurm / "sweep.sbatch").string()),
            std::string::npos)
      << dry.out;
  EXPECT_NE(dry.out.find("--dependency=afterok:"), std::string::npos) << dry.out;
  EXPECT_FALSE(fs::exists(slurm / "submission.json"));  // nothing was submitted
  EXPECT_FALSE(fs::exists(dir_.path() / "out" / "results.csv"));

  // Each task as Slurm starts it, then the merge: the table of a local run, byte for byte.
  for (int task = 1; task <= 3; ++task) {
    const ProcessResult r = runProcess({"env", "SLURM_ARRAY_TASK_ID=" + std::to_string(task),
                                        "bash", (slurm / "sweep.sbatch").string()});
    ASSERT_EQ(r.status, 0) << r.err << r.out;
  }
  const ProcessResult merged = runProcess({"bash", (slurm / "merge.sbatch").string()});
  ASSERT_EQ(merged.status, 0) << merged.err << merged.out;
  ASSERT_EQ(runPenumbra(dir_.path(), "sweep study.yaml -o local -q --device cpu").status, 0);
  const std::string local = readText(dir_.path() / "local" / "results.csv");
  EXPECT_EQ(testing::lines(local).size(), 7u);
  EXPECT_EQ(readText(dir_.path() / "out" / "results.csv"), local);
}

TEST_F(SlurmDryRun, OptionsThatDoNotGoTogether) {
  const auto status = [&](const std::string& arguments) {
    return runPenumbra(dir_.path(), arguments).status;
  };
  EXPECT_EQ(status("sweep study.yaml -o out --shards 2"), 1);                    // needs --slurm
  EXPECT_EQ(status("sweep study.yaml -o out --dry-run"), 1);                     // needs --slurm
  EXPECT_EQ(status("sweep study.yaml -o out --slurm --dry-run"), 1);             // no --shards
  EXPECT_EQ(status("sweep study.yaml -o out --slurm --shards 7 --dry-run"), 1);  // 6 cases
  EXPECT_EQ(status("sweep study.yaml -o out --slurm --shards 2 --shard 1/2 --dry-run"), 1);
  const testing::Result resume =
      runPenumbra(dir_.path(), "sweep study.yaml -o out --slurm --resume --dry-run");
  EXPECT_EQ(resume.status, 1);
  EXPECT_NE(resume.err.find("holds no Slurm submission"), std::string::npos) << resume.err;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
}

}  // namespace
}  // namespace penumbra
