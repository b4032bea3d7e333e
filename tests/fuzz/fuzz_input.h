#pragma once
// Turns the fuzzer's bytes into numbers and choices. libFuzzer mutates bytes; a target that
// reads them through this class sees small integers, ranges and picks, so a mutation of one
// byte changes one decision. When the bytes run out every read returns its lowest value: any
// input, even an empty one, is a complete test case. (Clang's FuzzedDataProvider does the same;
// this one also builds with GCC, where the targets replay their corpora as plain tests.)

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace stepwise::fuzz {

class FuzzInput {
public:
    FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::uint32_t bits32() {
        std::uint32_t value = 0;
        for (int i = 0; i < 4; ++i) value = (value << 8) | byte();
        return value;
    }
    /// An integer in [low, high].
    int integer(int low, int high) {
        const std::uint32_t span = std::uint32_t(high - low) + 1;
        return low + int((span <= 256 ? byte() : bits32()) % span);
    }
    bool flag() { return (byte() & 1) != 0; }
    /// A number in [low, high], 2^32 steps.
    double uniform(double low, double high) { return low + (high - low) * (bits32() / 4294967295.0); }
    /// A positive number between low and high spread evenly over the decades between them.
    double logUniform(double low, double high) { return std::exp(uniform(std::log(low), std::log(high))); }
    /// Three numbers in [low, high], read x, y, z in that order. (Never write
    /// Vec3(input.uniform(..), input.uniform(..), ..): a call's arguments are evaluated in an
    /// unspecified order, so GCC and Clang would read the same bytes into different axes.)
    Eigen::Vector3d vector(double low, double high) {
        const double x = uniform(low, high);
        const double y = uniform(low, high);
        const double z = uniform(low, high);
        return Eigen::Vector3d(x, y, z);
    }
    bool empty() const { return position_ >= size_; }

private:
    std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }

    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t position_ = 0;
};

/// Stops the program with a message: a failed invariant must reach libFuzzer as a crash (and a
/// plain replay run as a failed test), with the reason printed first.
[[noreturn]] void invariantFailed(const char* target, const char* what, double value, double limit);

#define STEPWISE_FUZZ_CHECK(target, condition, value, limit) \
    do {                                                      \
        if (!(condition)) ::stepwise::fuzz::invariantFailed(target, #condition, double(value), double(limit)); \
    } while (false)

}  // namespace stepwise::fuzz
