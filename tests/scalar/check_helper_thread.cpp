// A thread kept for many tasks (numeric/scalar/include/impact3d/scalar/helper_thread.hpp): each task
// started runs once and is finished when wait() returns, what a task throws comes out of wait() and leaves the thread serving,
// and a helper destroyed with a task still running finishes it first. Known answers by counting.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "impact3d/scalar/helper_thread.hpp"

namespace check_helper_thread {

using impact3d::HelperThread;

TEST_CASE("every task started runs once, and is done when wait returns", "[helper]") {
  HelperThread helper;
  helper.wait();  // nothing started: returns at once
  long sum = 0;   // written by the helper, read here only after wait()
  constexpr int kTasks = 2000;
  for (int i = 1; i <= kTasks; ++i) {
    helper.start([&sum, i] { sum += i; });
    helper.wait();
    REQUIRE(sum == static_cast<long>(i) * (i + 1) / 2);
  }
  CHECK(sum == static_cast<long>(kTasks) * (kTasks + 1) / 2);
}

TEST_CASE("what a task throws comes out of wait, and the helper serves on", "[helper]") {
  HelperThread helper;
  int thrown = 0, served = 0;
  for (int i = 0; i < 100; ++i) {
    helper.start([i] {
      if (i % 2) throw std::runtime_error("odd");
    });
    try {
      helper.wait();
      ++served;
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "odd");
      ++thrown;
    }
  }
  CHECK(thrown == 50);
  CHECK(served == 50);
  helper.wait();  // the error was taken: nothing more is thrown
}

TEST_CASE("a helper destroyed with its task running finishes the task first", "[helper]") {
  std::atomic<int> finished{0};
  int helpers = 0;
  for (; helpers < 20; ++helpers) {
    HelperThread helper;
    helper.start([&finished] {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      ++finished;
    });
  }
  CHECK(finished == helpers);
}

}  // namespace check_helper_thread
