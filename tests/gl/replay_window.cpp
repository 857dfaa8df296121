// tests/gl/replay_window.cpp — glut_shapes_lab_replay_window: the replay in a
// freeglut window. This use_freeglut_shapes, linked into the program itself,
// replaces the library's, so the window never hands the shapes to freeglut.
#include "gl/glut_shapes.h"

void gllab::use_freeglut_shapes() {}
