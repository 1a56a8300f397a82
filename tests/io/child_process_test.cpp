// The registry of child processes (common/io/child_process.hpp): stop_children() ends the whole
// process group of every registered child, a forgotten child is left alone, and the lock an
// interruption takes cannot be had while another thread works under it.

#include "io/child_process.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <future>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

// A child that leads a process group of its own and sleeps; its own child (a grandchild, in
// the same group) sleeps too. Returns the leader's pid.
pid_t sleeping_group() {
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpgid(0, 0);
    if (::fork() == 0) ::pause();
    ::pause();
    ::_exit(0);
  }
  ::setpgid(child, child);  // both sides set it: no race with the kill below
  return child;
}

TEST(ChildProcessTest, StopChildrenEndsTheWholeGroupOfARegisteredChild) {
  const pid_t child = sleeping_group();
  ASSERT_GT(child, 0);
  mcrt::without_interruption([&] { mcrt::stop_on_interrupt(child); });
  mcrt::stop_children();  // waits for the leader
  EXPECT_EQ(::waitpid(child, nullptr, WNOHANG), -1) << "the leader was reaped by stop_children";
  // The grandchild was killed with its group: kill(-group) finds no process left (a zombie
  // still counts, so give init a moment to reap it).
  bool gone = false;
  for (int attempt = 0; attempt < 100 && !gone; ++attempt) {
    gone = ::kill(-child, 0) != 0 && errno == ESRCH;
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_TRUE(gone) << "a process of the child's group survived";
  mcrt::forget_child(child);
}

TEST(ChildProcessTest, AForgottenChildIsLeftAlone) {
  const pid_t child = sleeping_group();
  ASSERT_GT(child, 0);
  mcrt::stop_on_interrupt(child);
  mcrt::forget_child(child);
  mcrt::stop_children();
  EXPECT_EQ(::kill(child, 0), 0) << "a forgotten child was killed";
  ::kill(-child, SIGKILL);
  ::waitpid(child, nullptr, 0);
}

TEST(ChildProcessTest, TheLockWaitsForWorkUnderIt) {
  std::promise<void> inside, release;
  std::thread worker([&] {
    mcrt::without_interruption([&] {
      inside.set_value();
      release.get_future().wait();
    });
  });
  inside.get_future().wait();
  EXPECT_FALSE(mcrt::hold_interruption_lock(std::chrono::milliseconds(50)));
  release.set_value();
  worker.join();
}

}  // namespace
