// The command facade (command.h) over CLI11: each function is the CLI11 call it stands for.
#include "app/command.h"

#include <CLI/CLI.hpp>

#include <map>
#include <utility>

namespace stepwise {

namespace {

/// A choice's value as an enum, so CLI11 types, shows and converts a choice exactly as it does an
/// option of the chapter's own enum (type ENUM, each name mapped to its enum's value).
enum class ChoiceValue : int {};

}  // namespace

CommandOption CommandOption::required() {
    option_->required();
    return *this;
}

CommandOption CommandOption::range(int min, int max) {
    option_->check(CLI::Range(min, max));
    return *this;
}

CommandOption CommandOption::range(long min, long max) {
    option_->check(CLI::Range(min, max));
    return *this;
}

CommandOption CommandOption::range(float min, float max) {
    option_->check(CLI::Range(min, max));
    return *this;
}

CommandOption CommandOption::range(double min, double max) {
    option_->check(CLI::Range(min, max));
    return *this;
}

CommandOption CommandOption::oneOf(const std::vector<std::string>& names) {
    option_->check(CLI::IsMember(names));
    return *this;
}

bool CommandOption::given() const { return option_->count() > 0; }

Command Command::addSubcommand(const std::string& name, const std::string& description) const {
    return Command(*app_->add_subcommand(name, description));
}

CommandOption Command::addOption(const std::string& name, std::string& value, const std::string& help) const {
    return CommandOption(app_->add_option(name, value, help));
}

CommandOption Command::addOption(const std::string& name, int& value, const std::string& help) const {
    return CommandOption(app_->add_option(name, value, help));
}

CommandOption Command::addOption(const std::string& name, long& value, const std::string& help) const {
    return CommandOption(app_->add_option(name, value, help));
}

CommandOption Command::addOption(const std::string& name, std::uint32_t& value, const std::string& help) const {
    return CommandOption(app_->add_option(name, value, help));
}

CommandOption Command::addOption(const std::string& name, float& value, const std::string& help) const {
    return CommandOption(app_->add_option(name, value, help));
}

CommandOption Command::addOption(const std::string& name, double& value, const std::string& help) const {
    return CommandOption(app_->add_option(name, value, help));
}

CommandOption Command::addFlag(const std::string& name, bool& value, const std::string& help) const {
    return CommandOption(app_->add_flag(name, value, help));
}

CommandOption Command::addChoiceValue(const std::string& name, const std::vector<std::pair<std::string, int>>& choices,
                                      const std::string& help, std::function<void(int)> choose) const {
    std::map<std::string, ChoiceValue> values;
    for (const auto& [key, value] : choices) values[key] = static_cast<ChoiceValue>(value);
    CLI::Option* option = app_->add_option_function<ChoiceValue>(
        name, [choose = std::move(choose)](const ChoiceValue& chosen) { choose(static_cast<int>(chosen)); }, help);
    option->transform(CLI::CheckedTransformer(values, CLI::ignore_case));
    return CommandOption(option);
}

void Command::onParsed(std::function<void()> run) const { app_->callback(std::move(run)); }

}  // namespace stepwise
