// common/gl/glu_nurbs.h — GLU's NURBS renderer for spline-core curves and
// surfaces: one object, every property from one struct, errors as frame
// errors, and a capture mode that hands back what GLU tessellated.
//
//   gllab::GluNurbs glu({.sampling_method = GLU_DOMAIN_DISTANCE, .u_step = 20, .v_step = 20});
//   glu.draw_surface(hill, "trimmed hill");        // GL draws it (rendering mode)
//   gllab::SurfaceCapture c = glu.capture_surface(hill, "trimmed hill");
//   c.mesh.triangles.size();                       // triangles exactly as GLU emitted them
//
// What the wrapper does so that no lab converts by hand (docs/glu.md):
//  - curves go to gluNurbsCurve as GL_MAP1_VERTEX_3 (polynomial) or
//    GL_MAP1_VERTEX_4 (rational, premultiplied (w x, w y, w z, w)); surfaces
//    to gluNurbsSurface as GL_MAP2_VERTEX_3 / GL_MAP2_VERTEX_4; order = p + 1;
//  - every trim loop of a surface goes between gluBeginTrim / gluEndTrim, a
//    polyline piece as gluPwlCurve (GLU_MAP1_TRIM_2), a curve piece as
//    gluNurbsCurve (GLU_MAP1_TRIM_2, or GLU_MAP1_TRIM_3 premultiplied (w u, w v, w));
//  - a 2D curve (dimension 2, z = 0) goes as it is, in the plane z = 0: that is
//    also how a lab draws a trim curve in its (u, v) square;
//  - GLU errors are reported with report_frame_error (harness/lab.h) as one
//    line naming the call and the lab's name for the object, e.g.
//    "gluNurbsSurface (trimmed hill): GLU NURBS error 28 (intersecting or misoriented trim curves)".
//    The window shows it, the headless runner exits 1.
//
// GLU 9.0.2 finds a misoriented or crossing trim loop (NURBS error 28) and an
// unconnected trim curve (error 31) but loses both on the way to its error
// callback (a longjmp into a dead frame; glu_errors.h, "errors GLU finds and
// then loses"). The wrapper catches that longjmp and reports them like any
// other GLU error.
//
// GLU passes its error callback no user data (GLU 9.0.2 has no
// GLU_NURBS_ERROR_DATA: measured, the enum is not in glu.h and a callback
// registered under the next free number is never called). GLU calls it
// synchronously from inside the gluNurbs* call that failed, so the wrapper
// keeps a thread-local pointer to the call in progress; that pointer is set
// only while one of the functions below runs.
//
// Data GLU cannot check: GLU infers the number of control points from the
// knot count (knots - order), so a knot array longer than the points would
// make it read past them. The wrapper refuses such shapes, non-finite values
// and values beyond float range with a frame error naming them, and passes
// everything else to GLU unchanged (decreasing knots, reversed trims, ...),
// so the labs see GLU's own reaction to bad data.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "spline/tessellate.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab {

/// The matrices GLU samples with when auto-load is off (gluLoadSamplingMatrices):
/// column-major 4x4 like glGetFloatv(GL_MODELVIEW_MATRIX), viewport x, y, w, h.
struct SamplingMatrices {
  std::array<GLfloat, 16> modelview{};
  std::array<GLfloat, 16> projection{};
  std::array<GLint, 4> viewport{};

  /// The current GL matrices and viewport (needs a current context).
  static SamplingMatrices from_gl();
};

/// Every GLU NURBS property. The defaults are GLU's own (read back with
/// gluGetNurbsProperty from a new object, GLU 9.0.2).
struct GluNurbsProperties {
  /// GLU_SAMPLING_METHOD: GLU_PATH_LENGTH (longest edge in pixels <=
  /// sampling_tolerance), GLU_PARAMETRIC_ERROR (distance in pixels <=
  /// parametric_tolerance), GLU_DOMAIN_DISTANCE (u_step, v_step samples per
  /// unit of parameter), GLU_OBJECT_PATH_LENGTH / GLU_OBJECT_PARAMETRIC_ERROR
  /// (the same tolerances in object units).
  GLenum sampling_method = GLU_PATH_LENGTH;
  float sampling_tolerance = 50;     // GLU_SAMPLING_TOLERANCE (> 0)
  float parametric_tolerance = 0.5f; // GLU_PARAMETRIC_TOLERANCE (> 0)
  float u_step = 100, v_step = 100;  // GLU_U_STEP, GLU_V_STEP (> 0)
  /// GLU_DISPLAY_MODE: GLU_FILL, GLU_OUTLINE_POLYGON (the tessellation's
  /// edges), GLU_OUTLINE_PATCH (patch boundaries and trim curves).
  GLenum display_mode = GLU_FILL;
  bool culling = false;  // GLU_CULLING: skip patches outside the view volume
  /// GLU_AUTO_LOAD_MATRIX: true reads the GL matrices at every gluBegin*;
  /// false uses sampling_matrices, which must then be given. It matters for
  /// the screen-space methods and culling. The object-space methods always
  /// run with auto-load off: choosing one turns it off inside GLU (measured),
  /// and turning it back on made GLU tessellate one bicubic patch into 76
  /// million vertices, then crash. So for them this field is ignored and
  /// properties() reports false.
  bool auto_load_matrix = true;
  std::optional<SamplingMatrices> sampling_matrices;

  /// The properties a GLU NURBS object has now (gluGetNurbsProperty): what a
  /// lab set on its own renderer with gluNurbsProperty, so that a capture
  /// (GluNurbs below) samples exactly as the lab's drawing does. With
  /// auto-load off the current GL matrices become the sampling matrices
  /// (GLU has no call that reads its own back).
  static GluNurbsProperties of(GLUnurbs* nurb);
};

/// "GLU_DOMAIN_DISTANCE" for GLU_DOMAIN_DISTANCE (and the other method and
/// display-mode enums); "0x1234" for anything else.
std::string glu_enum_name(GLenum value);

/// Does a method (or culling) need matrices: GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR.
bool samples_in_screen_space(GLenum sampling_method);

/// How rational control points reach GLU.
enum class RationalFeed {
  /// (w x, w y, w z, w) and trims (w u, w v, w): what GLU expects.
  kPremultiplied,
  /// The classic mistake, on purpose (lab 16 shows it): (x, y, z, w) passed
  /// as if premultiplied, so GLU draws the curve with control points P / w.
  /// Applies to every rational array of the call, trim curves included.
  kMistakeNotPremultiplied,
};

/// One error GLU (or the wrapper) raised during a call.
struct GluError {
  GLenum code = 0;      // GLU_NURBS_ERROR1..37, another GLU code, or 0 for the wrapper's own
  int nurbs_error = 0;  // 1..37 for GLU_NURBS_ERRORn, else 0
  std::string message;  // the line given to report_frame_error
};

/// One GLU primitive as it came through the callbacks.
struct GluPrimitive {
  GLenum mode = 0;          // GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_TRIANGLES, GL_QUAD_STRIP, GL_LINE_STRIP, ...
  std::size_t first = 0;    // its first vertex in the capture's vertex list
  std::size_t count = 0;    // how many vertices GLU sent for it
};

/// A polyline from a curve (or a surface outline), with each vertex's parameter.
struct CapturedPolyline {
  std::vector<spline::Vec3> points;
  /// Curves: the curve parameter of each point, clamped to the domain (the
  /// float map lands a few ulps outside at its ends); empty for surface outlines.
  std::vector<double> u;
  bool closed = false;    // GL_LINE_LOOP
};

struct CurveCapture {
  std::vector<CapturedPolyline> polylines;  // one per GLU line primitive, in order
  std::vector<GluPrimitive> primitives;
  std::vector<GluError> errors;
  std::size_t vertex_count() const;
  bool ok() const { return errors.empty(); }
};

struct SurfaceCapture {
  /// Every vertex GLU sent, in order, with the normal and (u, v) current at
  /// that moment ((u, v) clamped to the domain: the float texture map lands
  /// a few ulps outside it at its edges); triangles made from its strips, fans, triangles, quad strips,
  /// quads and polygons: n - 2 per strip, fan or polygon, n / 3 per GL_TRIANGLES,
  /// 2 per quad. Triangles are not deduplicated or dropped when degenerate:
  /// their number is what GLU emitted. Strip triangles keep GL's winding
  /// (every other one reversed back).
  spline::Mesh mesh;
  /// Line primitives (GLU_OUTLINE_PATCH in capture mode), without uv.
  std::vector<CapturedPolyline> lines;
  std::vector<GluPrimitive> primitives;
  std::vector<GluError> errors;
  /// How many primitives of one GL mode GLU emitted.
  std::size_t count(GLenum mode) const;
  bool ok() const { return errors.empty(); }
};

/// A GLUnurbs object (gluNewNurbsRenderer ... gluDeleteNurbsRenderer).
/// Movable, not copyable. Needs no GL context to exist; drawing does.
class GluNurbs {
 public:
  /// Creates the object and sets every property (set()).
  explicit GluNurbs(const GluNurbsProperties& properties = {});
  ~GluNurbs();
  GluNurbs(GluNurbs&& other) noexcept;
  GluNurbs& operator=(GluNurbs&& other) noexcept;
  GluNurbs(const GluNurbs&) = delete;
  GluNurbs& operator=(const GluNurbs&) = delete;

  /// Sets every property in one go: the sampling method first (it changes
  /// GLU's auto-load flag), then the tolerances, steps, display mode,
  /// culling, auto-load and, with auto-load off, gluLoadSamplingMatrices.
  /// Refuses (frame error, properties unchanged, returns false) an unknown
  /// enum, a tolerance or step that is not > 0 and finite, auto-load off for
  /// a screen-space method or culling without sampling_matrices,
  /// sampling_matrices while auto-load is on (GLU would ignore them), and
  /// culling or sampling_matrices with an object-space method (it uses no
  /// matrices).
  bool set(const GluNurbsProperties& properties);
  /// The properties in effect (auto_load_matrix false for object-space methods).
  const GluNurbsProperties& properties() const;

  /// Rendering mode (GLU_NURBS_RENDERER): GLU draws with the current GL state.
  /// Surfaces are lit only with glEnable(GL_AUTO_NORMAL) (docs/glu.md). `name`
  /// names the object in error lines. Returns the errors (also reported).
  /// Needs a current GL context (else one frame error, nothing drawn).
  /// A 2D curve (dimension 2, z = 0) is fed as it is, (x, y, 0) or
  /// (w x, w y, 0, w), and lies in the plane z = 0; a trim piece's curve
  /// (x = u, y = v) draws the same way, in the (u, v) square.
  std::vector<GluError> draw_curve(const spline::BsplineCurve& curve, const std::string& name,
                                   RationalFeed feed = RationalFeed::kPremultiplied);
  std::vector<GluError> draw_surface(const spline::BsplineSurface& surface, const std::string& name,
                                     RationalFeed feed = RationalFeed::kPremultiplied);

  /// Capture mode (GLU_NURBS_TESSELLATOR with the _DATA callbacks): GLU's
  /// vertices, normals and primitives come back instead of being drawn. The
  /// parameter of every vertex comes from a texture-coordinate map whose
  /// control values are the Greville abscissae (spline::greville_abscissae:
  /// GLU evaluates u itself). Surface vertices arrive projected; curve
  /// vertices of a GL_MAP1_VERTEX_4 map arrive homogeneous and are projected
  /// here (measured, bench/peer_glu.cpp). Works without a GL context for
  /// GLU_DOMAIN_DISTANCE and the object-space methods, and for screen-space
  /// methods with auto-load off and sampling_matrices. Screen-space sampling
  /// with auto-load on and no current context is refused with a frame error:
  /// GLU would read matrices that are not there and silently return a few
  /// wrong vertices (measured: 14 for a bicubic patch that needs 466).
  CurveCapture capture_curve(const spline::BsplineCurve& curve, const std::string& name,
                             RationalFeed feed = RationalFeed::kPremultiplied);
  SurfaceCapture capture_surface(const spline::BsplineSurface& surface, const std::string& name,
                                 RationalFeed feed = RationalFeed::kPremultiplied);

  /// The GLU object itself, for experiments beyond this class.
  GLUnurbs* get() const { return nurbs_; }

 private:
  GLUnurbs* nurbs_ = nullptr;
  GluNurbsProperties properties_;
};

/// Is a GL context current (glGetString(GL_VERSION) answers)? Works in
/// OSMesa and GLX programs alike; false before a context exists.
bool gl_context_current();

}  // namespace gllab
