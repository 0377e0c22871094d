// The one contract every stream processor keeps (docs/architecture.md, "The pipeline"):
//   void prepare(const ProcessSpec& spec, <its own settings, by name>);  // may allocate
//   void reset() noexcept;            // back to silence, as just after prepare()
//   void process(<buffers>, int count) noexcept;  // any count from 0 to spec.max_block
//   int latency() const;              // the delay it adds, in samples at spec.sample_rate_hz
// A processor's own settings come in a struct with named fields or as values of distinct
// types, so no two can be swapped at a call.
#pragma once

#include <concepts>

namespace tactus {

// What a processor is prepared for.
struct ProcessSpec {
    double sample_rate_hz = 48000;
    int max_block = 4096;  // the largest count process() will be given
    int channels = 1;
};

// The parts of the contract a type can be checked for at compile time (prepare's own
// settings differ from processor to processor).
template <typename T>
concept Processor = requires(T processor, const T& prepared) {
    { processor.reset() }
    noexcept;
    { prepared.latency() } -> std::same_as<int>;
};

}  // namespace tactus
