// The supervisor against workers that really hang, abort and get killed.
// The workers here are small scripts that speak the worker protocol, so
// each fault happens for certain and at a known case.
#include "runner/supervisor.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "runner/case_result_json.h"

namespace snell {
namespace {

namespace fs = std::filesystem;

class SupervisorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("snell-supervisor-" + std::to_string(getpid()));
    fs::create_directories(dir_);
    CaseResult pass;
    pass.status = Status::Pass;
    pass.backend = "gl";
    // The script answers each case id with a Pass record carrying that id,
    // except for the faults named by the id.
    std::string record = toJson(pass).dump();
    record.replace(record.find("\"case\":\"\""), 9, "\"case\":\"'\"$id\"'\"");
    script_ = dir_ / "fake-worker";
    std::ofstream(script_) << "#!/bin/bash\n"
                              "while read -r id; do\n"
                              "  case \"$id\" in\n"
                              "    hang*) sleep 600 ;;\n"
                              "    abort*) echo \"about to abort on $id\" >&2; kill -ABRT $$ ;;\n"
                              "    selfkill*) kill -KILL $$ ;;\n"
                              "    garbage*) echo 'this is not json' ;;\n"
                              "    *) echo '"
                           << record
                           << "' ;;\n"
                              "  esac\n"
                              "done\n";
    fs::permissions(script_, fs::perms::owner_all);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<CaseResult> run(const std::vector<std::string>& ids, int jobs) {
    std::vector<Task> tasks;
    for (const std::string& id : ids) tasks.push_back({id, "gl", 2.0});
    SupervisorOptions options;
    options.executable = script_.string();
    options.shaders = dir_.string();
    options.jobs = jobs;
    std::size_t calls = 0;
    auto results = superviseTasks(tasks, options, [&](std::size_t, const CaseResult&) { ++calls; });
    EXPECT_EQ(calls, ids.size());
    return results;
  }

  fs::path dir_, script_;
};

TEST_F(SupervisorTest, EachFaultCostsOnlyItsOwnCase) {
  const std::vector<std::string> ids = {"a", "hang-1", "b", "abort-1", "c", "selfkill-1",
                                        "d", "garbage-1", "e"};
  for (int jobs : {1, 2}) {
    const std::vector<CaseResult> results = run(ids, jobs);
    ASSERT_EQ(results.size(), ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) EXPECT_EQ(results[k].caseId, ids[k]) << jobs;
    for (std::size_t k : {0u, 2u, 4u, 6u, 8u}) EXPECT_EQ(results[k].status, Status::Pass) << ids[k];
    EXPECT_EQ(results[1].status, Status::Timeout);
    EXPECT_NE(results[1].message.find("limit 2.0 s"), std::string::npos) << results[1].message;
    EXPECT_EQ(results[3].status, Status::Crash);
    EXPECT_NE(results[3].message.find("signal 6"), std::string::npos) << results[3].message;
    EXPECT_NE(results[3].message.find("about to abort on abort-1"), std::string::npos)
        << results[3].message;
    EXPECT_EQ(results[5].status, Status::Crash);
    EXPECT_NE(results[5].message.find("signal 9"), std::string::npos) << results[5].message;
    EXPECT_EQ(results[7].status, Status::Crash);
    EXPECT_NE(results[7].message.find("malformed result"), std::string::npos);
  }
}

TEST_F(SupervisorTest, AWorkerThatCannotStartIsNeverAPass) {
  SupervisorOptions options;
  options.executable = (dir_ / "no-such-binary").string();
  options.shaders = dir_.string();
  // posix_spawn reports a missing file either as an error or as exit 127.
  try {
    const auto results = superviseTasks({{"a", "gl", 2.0}}, options, nullptr);
    EXPECT_EQ(results.at(0).status, Status::Crash);
  } catch (const std::exception& error) {
    SUCCEED() << error.what();
  }
}

}  // namespace
}  // namespace snell
