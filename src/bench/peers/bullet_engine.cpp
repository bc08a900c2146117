// Bullet 3.24 (double precision) as docs/bench/peers.md sets it up "as a user would":
// btDiscreteDynamicsWorld with the sequential-impulse solver, Dbvt broad phase, default collision
// configuration and every solver default. Bullet multiplies the coefficients of the two bodies, so
// each body gets sqrt(mu) and sqrt(e). One stepSimulation(dt, 0) is exactly one step of dt.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>

#include "bench/engine.h"

namespace tumble::bench {
namespace {

struct BulletOptions {
  bool sleeping = true;   // Bullet's default deactivation; off = DISABLE_DEACTIVATION on every body
};

class BulletEngine : public Engine {
 public:
  BulletEngine(const BenchScene& scene, double dt, BulletOptions opt) : dt_(dt) {
    dispatcher_ = std::make_unique<btCollisionDispatcher>(&config_);
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), &broadphase_, &solver_, &config_);
    world_->setGravity(btVector3(scene.gravity.x(), scene.gravity.y(), scene.gravity.z()));
    const double mu = std::sqrt(scene.friction), e = std::sqrt(scene.restitution);
    if (scene.ground) addBody(std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), 0), nullptr, mu, e);
    for (const BoxBody& w : scene.walls) addBody(boxShape(w), &w, mu, e, /*is_static=*/true);
    first_moving_ = bodies_.size();
    for (const BoxBody& b : scene.bodies) {
      btRigidBody* body = addBody(boxShape(b), &b, mu, e);
      body->setLinearVelocity(btVector3(b.v.x(), b.v.y(), b.v.z()));
      body->setAngularVelocity(btVector3(b.w.x(), b.w.y(), b.w.z()));
      if (!opt.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
      if (scene.ccd) {
        // docs/bench/peers.md: motion threshold = smallest half-extent, swept sphere 0.8 of it.
        const double h = b.half_extents.minCoeff();
        body->setCcdMotionThreshold(h);
        body->setCcdSweptSphereRadius(0.8 * h);
      }
    }
  }

  ~BulletEngine() override {
    // The world touches its bodies while it is destroyed: remove them first.
    for (auto& b : bodies_) world_->removeRigidBody(b.get());
    world_.reset();
  }

  void step() override { world_->stepSimulation(dt_, 0); }

  void read(std::vector<BodyState>& out) const override {
    out.resize(bodies_.size() - first_moving_);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const btRigidBody& b = *bodies_[first_moving_ + i];
      const btTransform& t = b.getCenterOfMassTransform();
      const btQuaternion q = t.getRotation();
      const btVector3 &x = t.getOrigin(), &v = b.getLinearVelocity(), &w = b.getAngularVelocity();
      out[i] = {{x.x(), x.y(), x.z()}, Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()),
                {v.x(), v.y(), v.z()}, {w.x(), w.y(), w.z()}};
    }
  }

 private:
  // btBoxShape keeps the outer size and puts its margin (0.04 m, or 10 % of the smallest
  // half-extent when that is less) inside: the shape is exactly the box.
  static std::unique_ptr<btCollisionShape> boxShape(const BoxBody& b) {
    return std::make_unique<btBoxShape>(btVector3(b.half_extents.x(), b.half_extents.y(), b.half_extents.z()));
  }

  btRigidBody* addBody(std::unique_ptr<btCollisionShape> shape, const BoxBody* box, double mu, double e,
                       bool is_static = false) {
    const double mass = box && !is_static ? box->mass : 0;
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    btTransform pose;
    pose.setIdentity();
    if (box) {
      pose.setOrigin(btVector3(box->x.x(), box->x.y(), box->x.z()));
      pose.setRotation(btQuaternion(box->q.x(), box->q.y(), box->q.z(), box->q.w()));
    }
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
    info.m_startWorldTransform = pose;
    info.m_friction = mu;
    info.m_restitution = e;
    auto body = std::make_unique<btRigidBody>(info);
    world_->addRigidBody(body.get());
    shapes_.push_back(std::move(shape));
    bodies_.push_back(std::move(body));
    return bodies_.back().get();
  }

  double dt_;
  btDefaultCollisionConfiguration config_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::size_t first_moving_ = 0;
};

EngineSetting bulletSetting(const std::string& name, BulletOptions opt) {
  EngineSetting s = settingOf<BulletEngine>(name, "bullet", opt);
  if (!opt.sleeping)
    s.skip_reason = [](const BenchScene& scene) {
      // Sleeping matters only where bodies come to rest (docs/bench/peers.md runs it there).
      const bool rests = scene.kind == SceneKind::Rest || scene.kind == SceneKind::Stack ||
                         scene.kind == SceneKind::MassRatio || scene.kind == SceneKind::Pile;
      return rests ? std::string() : std::string("nothing comes to rest: same as bullet");
    };
  return s;
}

}  // namespace

// The version of the headers built against (Bullet has no run-time call): 324 for 3.24.
std::string bulletVersion() {
  const int v = btGetVersion();
  return std::to_string(v / 100) + "." + std::to_string(v % 100);
}

std::vector<EngineSetting> bulletSettings() {
  return {bulletSetting("bullet", {true}), bulletSetting("bullet-nosleep", {false})};
}

}  // namespace tumble::bench
