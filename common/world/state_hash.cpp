#include "world/state_hash.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace stepwise {

namespace {

class Fnv1a {
public:
    void bytes(const void* data, std::size_t size) {
        const auto* byte = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ byte[i]) * 0x100000001b3ULL;
    }
    void real(Real value) {
        if (value == 0) value = 0;  // -0 and +0 are the same state
        bytes(&value, sizeof value);
    }
    void vec3(const Vec3& v) {
        for (int i = 0; i < 3; ++i) real(v[i]);
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace

std::uint64_t stateHash(const World& world) {
    Fnv1a hash;
    // Fixed widths: World::frame is a long, 64 bits on Linux and 32 on Windows; the hash of one
    // state must be the same on both (the golden hashes, recordings replayed across builds).
    const std::int64_t frame = world.frame;
    hash.bytes(&frame, sizeof frame);
    hash.bytes(&world.time, sizeof world.time);
    for (const Body& body : world.bodies) {
        hash.vec3(body.transform.position);
        hash.vec3(body.transform.rotation.vec());
        hash.real(body.transform.rotation.w());
    }
    for (const Motion& motion : world.motions) {
        hash.vec3(motion.linearVelocity);
        hash.vec3(motion.angularVelocity);
    }
    return hash.value();
}

std::uint32_t bodyStateHash(const World& world, std::size_t body) {
    Fnv1a hash;
    const Body& state = world.bodies[body];
    hash.vec3(state.transform.position);
    hash.vec3(state.transform.rotation.vec());
    hash.real(state.transform.rotation.w());
    if (const Motion* motion = world.motionOf(static_cast<int>(body))) {
        hash.vec3(motion->linearVelocity);
        hash.vec3(motion->angularVelocity);
    }
    const std::uint64_t value = hash.value();
    return static_cast<std::uint32_t>(value ^ (value >> 32));
}

std::string hexHash(std::uint64_t hash) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(hash));
    return text;
}

}  // namespace stepwise
