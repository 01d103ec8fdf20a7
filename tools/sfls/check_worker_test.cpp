#include "tools/sfls/check_worker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace sfls {
namespace {

const std::string kCamera = "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 8\n0 0 0 1\n";

std::string sceneOf(int spheres) {
  std::string text = kCamera;
  for (int i = 0; i < spheres; ++i) text += "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  return text;
}

// The versions checked, in the order their checks were reported.
class Reports {
 public:
  CheckWorker::Checked callback() {
    return [this](const std::string&, std::shared_ptr<Analysis> analysis) {
      std::lock_guard lock(mutex_);
      versions_.push_back(analysis->version);
      changed_.notify_all();
    };
  }
  std::vector<std::int64_t> waitFor(std::int64_t version) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::seconds(30),
                      [&] { return !versions_.empty() && versions_.back() == version; });
    return versions_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::int64_t> versions_;
};

CheckJob job(std::int64_t version, std::string text) {
  return {"file:///a.sf", version, std::make_shared<const std::string>(std::move(text)), "/a.sf"};
}

TEST(CheckWorker, ChecksTheNewestOfABurstAndNoStaleOneAfterIt) {
  Reports reports;
  CheckWorker worker(reports.callback());
  for (int version = 1; version <= 5; ++version) worker.schedule(job(version, sceneOf(version)));
  std::vector<std::int64_t> versions = reports.waitFor(5);
  ASSERT_FALSE(versions.empty());
  EXPECT_EQ(versions.back(), 5);
  EXPECT_TRUE(std::is_sorted(versions.begin(), versions.end()));
  EXPECT_EQ(std::adjacent_find(versions.begin(), versions.end()), versions.end());
}

TEST(CheckWorker, StopsTheCheckOfAnOlderVersion) {
  Reports reports;
  CheckWorker worker(reports.callback());
  // A check of 300,000 objects takes far longer than the pause.
  worker.schedule(job(1, sceneOf(300'000)));
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  auto start = std::chrono::steady_clock::now();
  worker.schedule(job(2, kCamera));
  std::vector<std::int64_t> versions = reports.waitFor(2);
  EXPECT_EQ(versions, std::vector<std::int64_t>{2});
  // Stopped, the first check lets the second start at once.
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(CheckWorker, WaitsAnEighthOfTheLastChecksTimeForAFurtherEdit) {
  Reports reports;
  CheckWorker worker(reports.callback());
  CheckJob large = job(1, sceneOf(300'000));
  auto start = std::chrono::steady_clock::now();
  worker.schedule(std::move(large));
  reports.waitFor(1);
  auto firstTook = std::chrono::steady_clock::now() - start;
  start = std::chrono::steady_clock::now();
  worker.schedule(job(2, kCamera));
  reports.waitFor(2);
  // An eighth of the first check's time, at most kMaxWait, passes before
  // the second starts. The time seen here also holds the wait for the
  // report (an eighth of it: under a millisecond, less two for that).
  auto wait = std::min<std::chrono::steady_clock::duration>(firstTook / 8, CheckWorker::kMaxWait);
  EXPECT_GE(std::chrono::steady_clock::now() - start, wait - std::chrono::milliseconds(2));
}

TEST(CheckWorker, AnalysesTheFormatTheDiagnosticsAndTheOutline) {
  std::shared_ptr<Analysis> analysis = analyse(job(3, sceneOf(2)));
  EXPECT_EQ(analysis->version, 3);
  EXPECT_EQ(analysis->format, scene::Format::SceneFile);
  EXPECT_EQ(analysis->result.scene.objects.size(), 2u);
  EXPECT_EQ(analysis->outline.items.size(), 3u);
}

}  // namespace
}  // namespace sfls
