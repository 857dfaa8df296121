// common/gl/texture.cpp — see texture.h.
#include "gl/texture.h"

#include <vector>

namespace gllab {

GLuint make_checker_texture(int size, int square, const GLubyte light[3], const GLubyte dark[3]) {
  std::vector<GLubyte> texels(static_cast<std::size_t>(size) * size * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const GLubyte* c = ((x / square) + (y / square)) % 2 != 0 ? dark : light;
      GLubyte* t = &texels[3 * (static_cast<std::size_t>(y) * size + x)];
      t[0] = c[0], t[1] = c[1], t[2] = c[2];
    }
  GLuint name = 0;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return name;
}

}  // namespace gllab
