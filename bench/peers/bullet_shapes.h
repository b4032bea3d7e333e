#pragma once
// The peer's shapes (bullet_peer.h, docs/peers.md): each Stepwise shape as Bullet's, built in the
// body frame Bullet uses, with everything Bullet's shapes point into (a mesh's arrays, a height
// field's heights, the meshes' edge information) kept alive for the run. Internal to the peer:
// unlike bullet_peer.h, this header includes Bullet's.

#include "peers/bullet_peer.h"

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionShapes/btTriangleInfoMap.h>

#include <memory>
#include <string>
#include <vector>

namespace stepwise::peers::detail {

inline btVector3 btVec(const Vec3& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }
inline Vec3 vec(const btVector3& v) { return Vec3(Real(v.x()), Real(v.y()), Real(v.z())); }
btMatrix3x3 btMat(const Mat3& m);
Mat3 mat(const btMatrix3x3& m);
inline btTransform btPose(const Mat3& basis, const Vec3& origin) { return btTransform(btMat(basis), btVec(origin)); }

/// Bullet's body frame in the shape's frame: an origin and axes (the columns of a rotation). For
/// a moving body it is the principal frame at the centre of mass, because Bullet takes a diagonal
/// inertia only (the same choice Bullet's own btCompoundShape::calculatePrincipalAxisTransform
/// makes). For a height field it is where btHeightfieldTerrainShape centres its grid.
struct PrincipalFrame {
    Vec3 center = Vec3::Zero();
    Mat3 axes = Mat3::Identity();
    Vec3 inertia = Vec3::Zero();
    bool identity() const { return center.isZero(0) && axes.isIdentity(0); }
};

/// The principal frame of a body's mass (identity for a static body: no Motion).
PrincipalFrame principalFrame(const Motion* motion);

/// What Bullet's shapes of one run own or point into. Bullet's shapes hold raw pointers to their
/// arrays, so the arrays live here until the run ends (a vector moved into the list keeps its
/// buffer, so growing the list never moves an array Bullet points into). Members go in reverse
/// order: the shapes before what they point into.
struct ShapeStore {
    std::vector<std::vector<btScalar>> vertices;
    std::vector<std::vector<int>> indices;
    std::vector<std::vector<float>> heights;
    std::vector<std::unique_ptr<btTriangleIndexVertexArray>> meshes;
    std::vector<std::unique_ptr<btTriangleInfoMap>> edgeInfos;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
};

/// One body's shape as Bullet's.
struct BulletShape {
    btCollisionShape* shape = nullptr;
    /// The body takes Bullet's internal-edge correction: it needs CF_CUSTOM_MATERIAL_CALLBACK, and
    /// the run needs adjustInternalEdgeContact as Bullet's contact-added callback.
    bool internalEdges = false;
};

/// The shape of a body as Bullet's, in Bullet's body frame `frame`. A height field without holes
/// moves `frame.center` to the middle of Bullet's centred grid (a static body: nothing else reads
/// it). `label` names the body in errors; a height field whose holes cannot be left out throws
/// BulletUnsupported.
BulletShape makeBodyShape(ShapeStore& store, const Shape& shape, PrincipalFrame& frame, bool internalEdges,
                          const std::string& label);

/// Bullet's contact-added callback (gContactAddedCallback) for the meshes' internal edges: a
/// contact on a triangle of a mesh with edge information gets its normal corrected by Bullet's
/// btAdjustInternalEdgeContacts.
bool adjustInternalEdgeContact(btManifoldPoint& point, const btCollisionObjectWrapper* a, int partA, int indexA,
                               const btCollisionObjectWrapper* b, int partB, int indexB);

/// Bullet's contact-added callback is process-wide: this puts adjustInternalEdgeContact in for one
/// run (`on`), and what was there back after it. Only bodies flagged CF_CUSTOM_MATERIAL_CALLBACK
/// call it.
struct InternalEdgeCallback {
    ContactAddedCallback previous = gContactAddedCallback;
    explicit InternalEdgeCallback(bool on) {
        if (on) gContactAddedCallback = adjustInternalEdgeContact;
    }
    ~InternalEdgeCallback() { gContactAddedCallback = previous; }
    InternalEdgeCallback(const InternalEdgeCallback&) = delete;
    InternalEdgeCallback& operator=(const InternalEdgeCallback&) = delete;
};

}  // namespace stepwise::peers::detail
