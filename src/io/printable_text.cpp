#include "particlesim/scene.hpp"

namespace particlesim {

namespace {

void append_printable(std::string& text, std::string_view input, bool escape_quote) {
    for (const char c : input) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f && c != '\\' && !(escape_quote && c == '"')) {
            text += c;
        } else {
            constexpr char digits[] = "0123456789ABCDEF";
            text += "\\x";
            text += digits[byte >> 4];
            text += digits[byte & 15];
        }
    }
}

}  // namespace

std::string printable_text(std::string_view text) {
    std::string shown;
    append_printable(shown, text, false);
    return shown;
}

std::string quoted_text(std::string_view text) {
    std::string shown = "\"";
    append_printable(shown, text, true);
    return shown + "\"";
}

}  // namespace particlesim
