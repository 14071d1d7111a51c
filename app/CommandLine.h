#pragma once

#include <string>

namespace drytwin::app {

/// @brief What main() should do after the command line was parsed.
struct ParsedCommandLine {
    bool exitNow = false; ///< --help, --version or a usage error: return exitCode
    int exitCode = 0;
    bool gui = false; ///< no subcommand: open the main window
    std::string guiDataPath;
    std::string screenshotPath; ///< GUI: save a PNG of the window once the data is shown, then quit
    std::string projectPath;    ///< GUI: open this project at start
    std::string language;       ///< GUI: "en" or "zh_CN" (empty: the saved choice, else the locale)
    std::string modelPath;      ///< GUI: open this model file with the data
    std::string runActions;     ///< GUI: comma-separated actions to run after loading
};

/// @brief The `drytwin` command line (CONTRACT.md §2), built on CLI11.
class CommandLine {
public:
    CommandLine();
    ~CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    ParsedCommandLine parse(int argc, char** argv);
    /// @brief Runs the parsed subcommand headless; returns the contract's exit code.
    int run();

private:
    struct Impl;
    Impl* m_impl;
};

} // namespace drytwin::app
