// common/image/pam.cpp — PAM (P7) encode and decode, as pam.h describes.
#include "image/pam.h"

#include <sstream>

namespace gllab {

std::string encode_pam(const Image& img) {
  std::ostringstream header;
  header << "P7\nWIDTH " << img.width << "\nHEIGHT " << img.height
         << "\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n";
  std::string bytes = header.str();
  bytes.append(reinterpret_cast<const char*>(img.rgba.data()), img.rgba.size());
  return bytes;
}

Image decode_pam(const std::string& bytes, const std::string& source) {
  std::size_t at = 0;
  Image img = decode_pam_at(bytes, at, source);
  if (at != bytes.size())
    throw ImageError("decode_pam: " + source + ": " + std::to_string(bytes.size() - at) + " bytes after the image");
  return img;
}

Image decode_pam_at(const std::string& bytes, std::size_t& at, const std::string& source) {
  const std::string where = "decode_pam: " + source + ": ";
  if (bytes.compare(at, 3, "P7\n") != 0)
    throw ImageError(where + "not a PAM image (" + std::to_string(bytes.size() - at) + " bytes, no P7 header)");
  const std::size_t end = bytes.find("ENDHDR\n", at);
  if (end == std::string::npos) throw ImageError(where + "PAM header without ENDHDR");
  std::istringstream header(bytes.substr(at + 3, end - at - 3));
  long width = 0, height = 0, depth = 0, maxval = 0;
  std::string tupltype;
  for (std::string key; header >> key;) {
    if (key == "WIDTH") header >> width;
    else if (key == "HEIGHT") header >> height;
    else if (key == "DEPTH") header >> depth;
    else if (key == "MAXVAL") header >> maxval;
    else if (key == "TUPLTYPE") header >> tupltype;
    else throw ImageError(where + "unknown PAM header field '" + key + "'");
  }
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
    throw ImageError(where + "PAM size " + std::to_string(width) + "x" + std::to_string(height) + " is not sensible");
  if (depth != 4 || maxval != 255 || tupltype != "RGB_ALPHA")
    throw ImageError(where + "PAM is DEPTH " + std::to_string(depth) + " MAXVAL " + std::to_string(maxval) +
                     " TUPLTYPE " + tupltype + " (expected 4, 255, RGB_ALPHA)");
  const std::size_t start = end + 7, expected = static_cast<std::size_t>(width) * height * 4;
  if (bytes.size() - start < expected)
    throw ImageError(where + "truncated PAM: " + std::to_string(expected) + " pixel bytes expected, " +
                     std::to_string(bytes.size() - start) + " present");
  Image img(static_cast<int>(width), static_cast<int>(height));
  img.rgba.assign(bytes.begin() + static_cast<std::ptrdiff_t>(start),
                  bytes.begin() + static_cast<std::ptrdiff_t>(start + expected));
  at = start + expected;
  return img;
}

}  // namespace gllab
