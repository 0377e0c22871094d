// libFuzzer target: any bytes as one request to `tactus studio`'s handler (handler.hpp), laid
// out as "METHOD PATH[?QUERY]\nTOKEN\nBODY" (TOKEN "1": the session's own, anything else as
// it is). Whatever arrives: a status the handler documents, every error one line in JSON, and
// nothing served without the token.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz_check.hpp"
#include "handler.hpp"

namespace {

// "a=1&b=2" -> {a: 1, b: 2} (no decoding: the server hands the handler decoded values).
std::map<std::string, std::string> query_of(const std::string& text) {
    std::map<std::string, std::string> query;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find('&', start), text.size());
        const std::string pair = text.substr(start, end - start);
        const size_t equals = pair.find('=');
        query[pair.substr(0, equals)] = equals == std::string::npos ? "" : pair.substr(equals + 1);
        start = end + 1;
    }
    return query;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static tactus::cli::StudioSession session({});
    const std::string input(reinterpret_cast<const char*>(data), size);
    const size_t line1 = std::min(input.find('\n'), input.size());
    const size_t line2 = std::min(input.find('\n', line1 + 1), input.size());
    const std::string first = input.substr(0, line1);
    const std::string token =
        line1 < input.size() ? input.substr(line1 + 1, line2 - line1 - 1) : "";
    tactus::cli::StudioRequest request;
    const size_t space = first.find(' ');
    request.method = first.substr(0, space);
    const std::string target = space == std::string::npos ? "" : first.substr(space + 1);
    const size_t question = target.find('?');
    request.path = target.substr(0, question);
    if (question != std::string::npos) request.query = query_of(target.substr(question + 1));
    request.token = token == "1" ? session.token() : token;
    request.body = line2 < input.size() ? input.substr(line2 + 1) : "";

    const tactus::cli::StudioResponse response = tactus::cli::handle_request(session, request);
    if (!session.token_matches(request.token) && response.status != 403) std::abort();
    if (response.status != 200 && response.status != 400 && response.status != 403 &&
        response.status != 404)
        std::abort();
    if (response.status != 200) {
        const auto body = nlohmann::json::parse(response.body, nullptr, false);
        if (!body.is_object() || !body["error"].is_string()) std::abort();
        tactus::fuzz::check_message(body["error"].get<std::string>().c_str());
    }
    return 0;
}
