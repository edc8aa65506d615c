// What a view may skip without changing a pixel: an object whose bounding sphere lies wholly
// outside the view's frustum, and the faces of a closed mesh that no viewer outside it can see;
// and how many pixels an object covers at most (which simplified stand-in a drag frame needs) and
// where (which pixels a material change reaches).
// The GL renderer asks it for its camera and for each shadow-map view; pure maths, no GL.
#pragma once

#include <glm/glm.hpp>

#include "camera/camera.h"
#include "geometry/bounding_sphere.h"
#include "geometry/mesh_topology.h"
#include "render/shadow_projection.h"

namespace glint {

enum class CulledFaces { None, Back, Front };

// Seen from outside, a closed surface shows only the faces that turn towards the viewer (the
// first surface a ray from outside meets is where it enters the solid): cull the back faces of
// an outward mesh, the front faces of an inside-out one. Nothing for an open mesh, or when the
// viewer may be inside or the near plane may cut the mesh open (`viewerOutside` false).
CulledFaces culledFaces(MeshClosure closure, bool viewerOutside);

// Whether `bounds` lies wholly beyond the camera's near plane: the camera (perspective eye or
// orthographic near plane) is then outside it and no clipping opens it.
bool beyondNearPlane(const Camera& camera, const BoundingSphere& bounds);
// The same for a shadow map's view: an orthographic map is fitted around the scene (always);
// a perspective or cube map's light must stay farther from the sphere than the corners of its
// near plane (near · √(1 + 2 tan²(fov/2)) from the light).
bool beyondNearPlane(const ShadowProjection& projection, const BoundingSphere& bounds);

// Whether the sphere lies wholly outside the frustum of a world → clip matrix: behind one of its
// six planes, read off the matrix's rows (Gribb & Hartmann, "Fast extraction of viewing frustum
// planes from the world-view-projection matrix", 2001).
bool outsideFrustum(const glm::mat4& viewProjection, const BoundingSphere& bounds);

// An upper estimate of the pixels the sphere covers in a width × height image of the camera:
// the disc of its projected radius (radius / (distance · tan(fov/2)) of half the image height in
// perspective, radius / (height/2) of it in orthographic), at most the whole image (also when the
// camera is inside or the near plane cuts it).
double coveredPixels(const Camera& camera, const BoundingSphere& bounds, int width, int height);

// A rectangle of a frame's pixels, in GL's convention: x from the left column, y from the bottom row.
struct PixelRegion {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};
PixelRegion intersectionOf(const PixelRegion& a, const PixelRegion& b);
PixelRegion boundsOf(const PixelRegion& a, const PixelRegion& b);  // the smallest region holding both

// Rows [first, first + count) of a frame, counted from its bottom row; count 0: every row.
struct RowBand {
    int first = 0;
    int count = 0;
};

// The pixels of a width × height frame of the camera that the sphere may cover, any MSAA sample
// of them: the bounds of its projected outline, widened by a pixel; the whole frame when the
// sphere holds the eye or reaches behind it.
PixelRegion coveredRect(const Camera& camera, const BoundingSphere& bounds, int width, int height);

}  // namespace glint
