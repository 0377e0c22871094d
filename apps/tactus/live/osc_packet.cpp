#include "osc_packet.hpp"

#include <fmt/format.h>
#include <lo/lo.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace tactus::live {
namespace {

constexpr std::string_view kBundleTag{"#bundle\0", 8};
constexpr int kMaxDepth = 8;  // bundles in bundles

uint32_t big_endian_u32(const std::byte* p) {
    return (std::to_integer<uint32_t>(p[0]) << 24) | (std::to_integer<uint32_t>(p[1]) << 16) |
           (std::to_integer<uint32_t>(p[2]) << 8) | std::to_integer<uint32_t>(p[3]);
}

OscMessage decode_message(std::span<const std::byte> bytes) {
    // liblo's parser writes nothing but wants a non-const pointer; it reads a copy.
    std::vector<std::byte> copy(bytes.begin(), bytes.end());
    int result = 0;
    const std::unique_ptr<std::remove_pointer_t<lo_message>, decltype(&lo_message_free)> message(
        lo_message_deserialise(copy.data(), copy.size(), &result), &lo_message_free);
    if (!message)
        throw std::invalid_argument(fmt::format(
            "osc: a malformed message of {} bytes (liblo error {})", bytes.size(), result));
    OscMessage out;
    const size_t path_end = strnlen(reinterpret_cast<const char*>(copy.data()), copy.size());
    out.address.assign(reinterpret_cast<const char*>(copy.data()), path_end);
    const char* types = lo_message_get_types(message.get());
    lo_arg** argv = lo_message_get_argv(message.get());
    const int argc = lo_message_get_argc(message.get());
    for (int i = 0; i < argc; ++i) {
        OscArg a;
        a.type = types[i];
        // liblo's arguments are 4-byte aligned, its lo_arg union 8: read the bytes, not the union.
        const auto* bytes = reinterpret_cast<const char*>(argv[i]);
        const auto read = [&]<typename T>(T value) {
            std::memcpy(&value, bytes, sizeof value);
            return static_cast<double>(value);
        };
        switch (types[i]) {
            case LO_INT32:
                a.number = read(int32_t{});
                break;
            case LO_INT64:
                a.number = read(int64_t{});
                break;
            case LO_FLOAT:
                a.number = read(float{});
                break;
            case LO_DOUBLE:
                a.number = read(double{});
                break;
            case LO_TRUE:
                a.number = 1;
                break;
            case LO_FALSE:
                a.number = 0;
                break;
            case LO_STRING:
            case LO_SYMBOL:
                a.text = bytes;
                break;
            default:
                break;  // kept with its type: parse_osc refuses it by name
        }
        out.args.push_back(std::move(a));
    }
    return out;
}

void decode(std::span<const std::byte> bytes, int depth, std::vector<OscMessage>& out) {
    if (bytes.size() >= kBundleTag.size() &&
        std::memcmp(bytes.data(), kBundleTag.data(), kBundleTag.size()) == 0) {
        if (depth >= kMaxDepth) throw std::invalid_argument("osc: bundles nested too deep");
        size_t at = kBundleTag.size() + 8;  // the time tag
        if (bytes.size() < at) throw std::invalid_argument("osc: a bundle without its time tag");
        while (at < bytes.size()) {
            if (bytes.size() - at < 4) throw std::invalid_argument("osc: a truncated bundle");
            const uint32_t size = big_endian_u32(bytes.data() + at);
            at += 4;
            if (size == 0 || size % 4 != 0 || size > bytes.size() - at)
                throw std::invalid_argument(fmt::format(
                    "osc: a bundle element of {} bytes in {} left", size, bytes.size() - at));
            decode(bytes.subspan(at, size), depth + 1, out);
            at += size;
        }
        return;
    }
    out.push_back(decode_message(bytes));
}

}  // namespace

std::vector<OscMessage> decode_osc_packet(std::span<const std::byte> packet) {
    std::vector<OscMessage> messages;
    decode(packet, 0, messages);
    return messages;
}

std::vector<std::byte> encode_osc_message(const OscMessage& message) {
    const std::unique_ptr<std::remove_pointer_t<lo_message>, decltype(&lo_message_free)> m(
        lo_message_new(), &lo_message_free);
    for (const OscArg& a : message.args) {
        if (a.type == 'd')
            lo_message_add_double(m.get(), a.number);
        else if (a.type == 'i')
            lo_message_add_int32(m.get(), static_cast<int32_t>(a.number));
        else if (a.type == 's' || a.type == 'S')
            lo_message_add_string(m.get(), a.text.c_str());
        else
            lo_message_add_float(m.get(), static_cast<float>(a.number));
    }
    size_t size = 0;
    void* bytes = lo_message_serialise(m.get(), message.address.c_str(), nullptr, &size);
    if (!bytes) throw std::runtime_error("osc: a reply liblo could not serialise");
    std::vector<std::byte> out(static_cast<std::byte*>(bytes),
                               static_cast<std::byte*>(bytes) + size);
    std::free(bytes);
    return out;
}

}  // namespace tactus::live
