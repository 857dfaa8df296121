// common/gl/scene.h — small set-ups most labs share.
#pragma once

#include <string>
#include <vector>

#include "gl/text.h"

namespace gllab {

class State;

/// Orthographic projection showing at least [-half_width, half_width] x
/// [-half_height, half_height] with square pixels in a width x height
/// viewport; z from -depth to depth. Leaves GL_MODELVIEW current and identity.
void ortho_fit(int width, int height, double half_width, double half_height, double depth = 10);

/// One white directional light from the upper left front, with
/// GL_COLOR_MATERIAL (glColor sets ambient and diffuse) and GL_NORMALIZE.
void enable_headlight();

/// The orbit camera of a 3D view (harness/lab.h kOrbit, State::camera), on
/// top of the lab's own camera: call it right after the projection (and the
/// headlight, which then stays with the eye), before the lab's own turns.
/// It scales the projection by camera.zoom in x and y, then turns the
/// modelview by camera.pitch about x and camera.yaw about y, about the eye
/// space origin: the centre of an ortho_fit view. The default camera changes
/// nothing, so the reference images are the lab's own camera.
void apply_orbit(const State& s);

/// Turns the current modelview so that a z-up scene is seen from `elevation`
/// degrees above its xy-plane (90: straight down), turned by `azimuth`
/// degrees about z: the fixed tilted camera of the surface labs.
void look_from_above(double elevation, double azimuth);

/// Text centred on the window position of the object-space point (x, y, z)
/// under the current matrices, shifted by (dx, dy) pixels (dy downwards).
void draw_label(double x, double y, double z, const std::string& text, Rgb colour,
                int dx = 0, int dy = 0);

/// The window pixel (x from the left, y down from the top, as draw_text
/// takes them) of the lab point (x, y, z) under the current matrices, rounded
/// to the nearest pixel. False when the point does not project.
bool window_pixel(double x, double y, double z, int& px, int& py);

/// draw_text_panel (one colour per line) with its top-left corner at the
/// window position of the lab point (x, y, z) under the current matrices, so
/// the panel stays beside what it describes when the window is resized.
void draw_text_panel_at(double x, double y, double z, const std::vector<std::string>& lines,
                        const std::vector<Rgb>& colours);

}  // namespace gllab
