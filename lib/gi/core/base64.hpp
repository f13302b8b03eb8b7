#pragma once
#include <string>
#include <string_view>

namespace gi {

// RFC 4648 base64 of the bytes, with padding: binary data inside a text file (a
// picture in an SVG's data URL, the viewer's typed arrays in its JSON).
std::string base64(std::string_view bytes);

}  // namespace gi
