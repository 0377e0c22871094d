// The studio's page: page.html (markup, style and script in one file), embedded at build time.
#pragma once

#include <string_view>

namespace tactus::cli {

std::string_view studio_page();

}  // namespace tactus::cli
