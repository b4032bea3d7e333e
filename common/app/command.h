#pragma once
// The command line as chapters see it: a Command adds subcommands, options and flags and runs a
// callback once its command line is parsed. The `stepwise` program parses with CLI11, a large
// header library of templates; behind this small interface only common/app compiles it, so a
// chapter that adds a command (`collide`, `stress`, `record`) costs its unity build no CLI11.
// Each function is one CLI11 call (add_option, add_flag, check, ...) on a value of the same type,
// so option names, help, validation messages and exit codes are CLI11's own.
//
//     Command record = program.addSubcommand("record", "Run a scene and record it");
//     record.addOption("--output", args->output, "The recording file to write").required();
//     record.addOption("--frames", args->frames, "Frames to run").range(0L, 10000000L);
//     record.onParsed([args, &exitCode] { exitCode = runRecord(*args); });

#include "world/enum_names.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace stepwise {

/// An option just added, to refine: each call checks one more thing and returns the option, so
/// the refinements chain. A handle: the option itself belongs to its command's CLI11 parser.
class CommandOption {
public:
    explicit CommandOption(CLI::Option* option) : option_(option) {}

    /// Parsing fails when the option is missing ("--input is required").
    CommandOption required();
    /// The value must lie in [min, max] (CLI::Range: "Value 0 not in range 1 to 99"). The bounds'
    /// type is the one the range compares in, as CLI11's Range takes it.
    CommandOption range(int min, int max);
    CommandOption range(long min, long max);
    CommandOption range(float min, float max);
    CommandOption range(double min, double max);
    /// The value must be one of `names`, spelled exactly (CLI::IsMember).
    CommandOption oneOf(const std::vector<std::string>& names);
    /// True when the command line gave the option (a value of its own, not the default).
    bool given() const;

private:
    CLI::Option* option_;
};

/// A command of the program (the program itself, or one of its subcommands). A handle onto a
/// CLI::App, passed by value: what it adds belongs to the App, which outlives the parse.
class Command {
public:
    /// Not explicit: a chapter's install function takes the program's CLI::App as a Command.
    Command(CLI::App& app) : app_(&app) {}

    Command addSubcommand(const std::string& name, const std::string& description) const;

    /// An option with a value (`--frames 600`) or, for a name without dashes, a positional
    /// argument (`record SCENE`). The value is written when the command line is parsed.
    CommandOption addOption(const std::string& name, std::string& value, const std::string& help) const;
    CommandOption addOption(const std::string& name, int& value, const std::string& help) const;
    CommandOption addOption(const std::string& name, long& value, const std::string& help) const;
    CommandOption addOption(const std::string& name, std::uint32_t& value, const std::string& help) const;
    CommandOption addOption(const std::string& name, float& value, const std::string& help) const;
    CommandOption addOption(const std::string& name, double& value, const std::string& help) const;
    /// A flag without a value (`--time`): true when given.
    CommandOption addFlag(const std::string& name, bool& value, const std::string& help) const;

    /// One of an enum's names, matched ignoring case (`--density DENSE`), as CLI11's
    /// CheckedTransformer over a map of the names to the enum with CLI::ignore_case checks, lists
    /// and converts them.
    template <class E>
    CommandOption addChoice(const std::string& name, E& value, const Names<E>& names, const std::string& help) const {
        std::vector<std::pair<std::string, int>> choices;
        for (const auto& [key, listed] : names) choices.emplace_back(key, static_cast<int>(listed));
        return addChoiceValue(name, choices, help, [&value](int chosen) { value = static_cast<E>(chosen); });
    }

    /// Runs `run` once the command line is parsed, when it named this command.
    void onParsed(std::function<void()> run) const;

private:
    /// addChoice without the enum: `choose` gets the value (as an int) of the name given.
    CommandOption addChoiceValue(const std::string& name, const std::vector<std::pair<std::string, int>>& choices,
                                 const std::string& help, std::function<void(int)> choose) const;

    CLI::App* app_;
};

}  // namespace stepwise
