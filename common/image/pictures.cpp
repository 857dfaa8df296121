// common/image/pictures.cpp — the PNG files of pictures.h, assembled into the
// object with .incbin (the paths come from CMake: common/image/CMakeLists.txt).
#include "image/pictures.h"

#include <cstddef>
#include <cstdint>

__asm__(".pushsection .rodata\n"
        "gllab_face_a_begin:\n"
        ".incbin \"" GLLAB_FACE_A_PNG "\"\n"
        "gllab_face_a_end:\n"
        "gllab_face_b_begin:\n"
        ".incbin \"" GLLAB_FACE_B_PNG "\"\n"
        "gllab_face_b_end:\n"
        ".popsection\n");
extern "C" const std::uint8_t gllab_face_a_begin[], gllab_face_a_end[];
extern "C" const std::uint8_t gllab_face_b_begin[], gllab_face_b_end[];

namespace gllab {

Image embedded_picture(Picture picture) {
  if (picture == Picture::kFaceA)
    return decode_png(gllab_face_a_begin, std::size_t(gllab_face_a_end - gllab_face_a_begin),
                      "embedded picture examples/face_a.png");
  return decode_png(gllab_face_b_begin, std::size_t(gllab_face_b_end - gllab_face_b_begin),
                    "embedded picture examples/face_b.png");
}

}  // namespace gllab
