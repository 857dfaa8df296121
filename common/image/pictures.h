// common/image/pictures.h — pictures compiled into the programs that texture
// them, so that a lab needs no file at run time: examples/face_a.png and
// examples/face_b.png, the two faces of lab 28's morph (made by
// tools/make_faces; tests/deform/faces_test.cpp checks that the shipped files
// are what it draws). Rebuilding after editing a PNG puts the new picture in.
#pragma once

#include "image/image.h"

namespace gllab {

enum class Picture { kFaceA, kFaceB };

/// The picture, decoded (decode_png). Throws ImageError if the compiled-in
/// file is not a valid PNG (one replaced by something else, say).
Image embedded_picture(Picture picture);

}  // namespace gllab
