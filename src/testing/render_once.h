// Test support (not installed): a GoogleTest fixture for suites that read rendered images
// (testing/rendered_scene.h). The images are rendered once per test suite, into a folder of
// their own in the system's temporary directory, and removed after the suite's last test:
//   <temp>/hecal_<Suite::kRenderFolder>_<process id>
// The process id keeps test processes that run at the same time (ctest -j) apart.
//
// Use (CRTP): class MyTest : public testing::RenderOnce<MyTest, Base> { public: static
// constexpr const char* kRenderFolder = "my_test"; static void Render(const path& dir); ... };
// Base is the fixture the suite builds on (::testing::Test by default; the CLI tests' CliTest).
// Render gets the folder created and empty. A failure while rendering fails every test of the
// suite (GoogleTest reports it at the suite's set-up).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace hecal::testing {

template <typename Suite, typename Base = ::testing::Test>
class RenderOnce : public Base {
 public:
  static void SetUpTestSuite() {
    std::filesystem::remove_all(RenderDir());
    std::filesystem::create_directories(RenderDir());
    Suite::Render(RenderDir());
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(RenderDir()); }

  static std::filesystem::path RenderDir() {
    return std::filesystem::temp_directory_path() /
           ("hecal_" + std::string(Suite::kRenderFolder) + "_" + std::to_string(::getpid()));
  }
};

}  // namespace hecal::testing
