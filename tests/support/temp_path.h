#pragma once
// Files a test writes go in a folder of the temporary directory that belongs to its process:
// ctest runs test cases as separate processes side by side (-j), and the presets' suites share
// one temporary directory, so two cases writing one fixed name would read each other's file.
// The folder is removed when the process ends.
//   const std::string input = test::tempPath("input.json");

#include <filesystem>
#include <string>
#include <system_error>

#ifdef _WIN32
#include <process.h>
#define STEPWISE_TEST_PID _getpid()
#else
#include <unistd.h>
#define STEPWISE_TEST_PID getpid()
#endif

namespace stepwise::test {

/// This process's folder in the temporary directory, made on first use.
inline const std::filesystem::path& tempFolder() {
    struct Folder {
        std::filesystem::path path;
        Folder() : path(std::filesystem::temp_directory_path() / ("stepwise-test-" + std::to_string(STEPWISE_TEST_PID))) {
            std::filesystem::remove_all(path);  // a folder a crashed process with the same id left
            std::filesystem::create_directories(path);
        }
        ~Folder() {
            std::error_code ignored;  // leaving a folder behind is no reason to fail at exit
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Folder folder;
    return folder.path;
}

/// A path named `name` in this process's folder.
inline std::filesystem::path tempPath(const std::string& name) { return tempFolder() / name; }

}  // namespace stepwise::test

#undef STEPWISE_TEST_PID
