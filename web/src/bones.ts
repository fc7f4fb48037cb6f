// A rig's figure beside its modal skin (docs/web.md#rig-motion-in-the-page): the bones drawn as
// lines between each body's ends, the joints as points (the pose editor picks them), and the
// skin by three.js linear blend skinning (`SkinnedMesh`, one bone per body; in the rig's
// materials too, sharing the modal skin's textures) — all moved by the body poses of the same
// mode coefficients. With the surface on (docs/design.md#surface-of-a-rig) the LBS skin carries
// the skin's harmonics as three.js morph targets, applied before the skin as in the glb:
// Σ_b w_ib T_b (x_i + d_i), exactly.
import * as THREE from "three";
import { CLAY } from "./deform";
import type { DrawnLook } from "./look";
import type { Rig } from "./rig-bundle";
import { normalising } from "./rig-bundle";
import { surfaceTargets } from "./rig-surface";
import type { RigSurface } from "./rig-surface";
import { SURFACE_FRAGMENT } from "./shaders";

/** Linear blend skinning with three.js's own skinning chunks; shaded like the modal skin (the
 * shared surface fragment: clay, or a material with its UVs and colours). */
const LBS_VERTEX = /* glsl */ `
#include <common>
#include <skinning_pars_vertex>
#include <morphtarget_pars_vertex>
out vec3 vViewPosition;
out vec3 vNormal;
#ifdef MATERIAL
in vec2 texcoord0;
out vec2 vUv0;
#ifdef UV1
in vec2 texcoord1;
out vec2 vUv1;
#endif
#ifdef VERTEX_COLOR
in vec4 vertexColor;
out vec4 vColor;
#endif
#endif
void main() {
  #include <skinbase_vertex>
  #include <begin_vertex>
  #include <morphtarget_vertex>
  #include <skinning_vertex>
#ifdef MATERIAL
  vUv0 = texcoord0;
#ifdef UV1
  vUv1 = texcoord1;
#endif
#ifdef VERTEX_COLOR
  vColor = vertexColor;
#endif
#endif
  vec4 mv = modelViewMatrix * vec4(transformed, 1.0);
  vViewPosition = -mv.xyz;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * mv;
}
`;

/** Relative morph targets (n*3 each) on a geometry, set before its mesh is made (the mesh then
 * holds one influence per target). */
function withTargets(geometry: THREE.BufferGeometry, targets: Float32Array[]): void {
  if (!targets.length) return;
  geometry.morphAttributes.position = targets.map((t) => new THREE.BufferAttribute(t, 3));
  geometry.morphTargetsRelative = true;
}

export class RigFigure {
  /** in the page's normalised units: scale σ about the skin's centre */
  readonly group = new THREE.Group();
  readonly skinned: THREE.SkinnedMesh;
  readonly lbsMaterial: THREE.ShaderMaterial;
  /** the LBS skin in the rig's materials (null: a rig drawn in clay) */
  readonly skinnedLook: THREE.SkinnedMesh | null = null;
  private readonly bones: THREE.LineSegments;
  private readonly joints: THREE.Points;
  private readonly picked: THREE.Points;
  private readonly skeletonBones: THREE.Bone[];
  private readonly rest: THREE.Matrix4[];

  /** `surface`: the skin's harmonics, its ripple drawn by `ripple` (null: none). */
  constructor(readonly rig: Rig, look: DrawnLook | null = null, surface: RigSurface | null = null) {
    const s = normalising(rig);
    this.group.matrixAutoUpdate = false;
    this.group.matrix.makeScale(s, s, s).setPosition(-rig.center[0] * s, -rig.center[1] * s,
      -rig.center[2] * s);
    this.group.matrixWorldNeedsUpdate = true;

    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(rig.vertices, 3));
    geometry.setIndex(new THREE.BufferAttribute(rig.faces, 1));
    geometry.computeVertexNormals();
    geometry.setAttribute("skinIndex", new THREE.Uint16BufferAttribute(rig.skinJoints, 4));
    geometry.setAttribute("skinWeight", new THREE.BufferAttribute(rig.skinWeights, 4));
    const targets = surface ? surfaceTargets(surface) : [];
    withTargets(geometry, targets);
    this.lbsMaterial = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3, vertexShader: LBS_VERTEX, fragmentShader: SURFACE_FRAGMENT,
      uniforms: { baseColor: { value: new THREE.Color().setHex(CLAY, THREE.SRGBColorSpace) },
        deformedNormalWeight: { value: 1 }, colorHarmonic: { value: -1 }, wire: { value: false } },
      side: THREE.DoubleSide,
    });
    this.skinned = new THREE.SkinnedMesh(geometry, this.lbsMaterial);
    this.skinned.frustumCulled = false;
    this.skeletonBones = Array.from({ length: rig.b }, () => {
      const bone = new THREE.Bone();
      bone.matrixAutoUpdate = false;
      bone.matrixWorldAutoUpdate = false; // set from the body poses, outside the scene graph
      return bone;
    });
    this.rest = Array.from({ length: rig.b }, (_, b) =>
      new THREE.Matrix4().fromArray(rig.boneMatrices, 16 * b));
    const inverses = Array.from({ length: rig.b }, (_, b) =>
      new THREE.Matrix4().fromArray(rig.bindMatrices, 16 * b));
    this.skinned.bindMode = THREE.DetachedBindMode;
    const skeleton = new THREE.Skeleton(this.skeletonBones, inverses);
    this.skinned.bind(skeleton, new THREE.Matrix4());
    if (look) {
      const drawn = look.drawnGeometry(rig.vertices, { skinIndex: [rig.skinJoints, 4],
        skinWeight: [rig.skinWeights, 4] });
      withTargets(drawn, targets.map((target) => look.gathered(target, 3)));
      this.skinnedLook = new THREE.SkinnedMesh(drawn, look.materialsWith(LBS_VERTEX));
      this.skinnedLook.frustumCulled = false;
      this.skinnedLook.bindMode = THREE.DetachedBindMode;
      this.skinnedLook.bind(skeleton, new THREE.Matrix4());
      for (const material of this.skinnedLook.material as THREE.ShaderMaterial[]) {
        material.uniforms.deformedNormalWeight = { value: 1 };
      }
    }

    const lines = new THREE.BufferGeometry();
    lines.setAttribute("position", new THREE.BufferAttribute(new Float32Array(rig.bodyEnds), 3));
    this.bones = new THREE.LineSegments(lines, new THREE.LineBasicMaterial({
      color: 0x7fd3ff, depthTest: false, transparent: true, opacity: 0.9 }));
    this.bones.renderOrder = 2;
    const points = new THREE.BufferGeometry();
    points.setAttribute("position", new THREE.BufferAttribute(
      new Float32Array(rig.jointPositions), 3));
    this.joints = new THREE.Points(points, new THREE.PointsMaterial({
      color: 0xffffff, size: 7, sizeAttenuation: false, depthTest: false }));
    this.joints.renderOrder = 3;
    const one = new THREE.BufferGeometry();
    one.setAttribute("position", new THREE.BufferAttribute(new Float32Array(3), 3));
    this.picked = new THREE.Points(one, new THREE.PointsMaterial({
      color: 0xffb347, size: 13, sizeAttenuation: false, depthTest: false }));
    this.picked.renderOrder = 4;
    this.group.add(this.skinned, this.bones, this.joints, this.picked);
    if (this.skinnedLook) this.group.add(this.skinnedLook);
    for (const object of [this.skinned, this.bones, this.joints, this.picked]) {
      object.frustumCulled = false;
    }
    this.show({ lbs: false, bones: false, joint: -1 });
  }

  /** What shows: the LBS skin (instead of the modal skin; in its materials when asked and it
   * has them), the bones and joints, the joint picked by the pose editor (−1: none). */
  show(what: { lbs: boolean; bones: boolean; joint: number; materials?: boolean }): void {
    const look = Boolean(what.materials && this.skinnedLook);
    this.skinned.visible = what.lbs && !look;
    if (this.skinnedLook) this.skinnedLook.visible = what.lbs && look;
    this.bones.visible = this.joints.visible = what.bones || what.joint >= 0;
    this.picked.visible = what.joint >= 0;
    if (what.joint >= 0) { // where the joint is drawn now (posed)
      const at = this.picked.geometry.getAttribute("position") as THREE.BufferAttribute;
      const joints = this.joints.geometry.getAttribute("position") as THREE.BufferAttribute;
      at.setXYZ(0, joints.getX(what.joint), joints.getY(what.joint), joints.getZ(what.joint));
      at.needsUpdate = true;
    }
  }

  /** Move bones, joints and the LBS skin to the body poses (column-major world matrices, file
   * units, `bodyMatrices`). */
  pose(matrices: Float32Array): void {
    const motion = new THREE.Matrix4(), inverse = new THREE.Matrix4(), p = new THREE.Vector3();
    const ends = this.bones.geometry.getAttribute("position") as THREE.BufferAttribute;
    this.skeletonBones.forEach((bone, b) => {
      bone.matrixWorld.fromArray(matrices, 16 * b);
      // the body's motion from rest: posed · rest⁻¹ moves its ends
      motion.multiplyMatrices(bone.matrixWorld, inverse.copy(this.rest[b]).invert());
      for (let e = 0; e < 2; e++) {
        p.fromArray(this.rig.bodyEnds, 6 * b + 3 * e).applyMatrix4(motion);
        ends.setXYZ(2 * b + e, p.x, p.y, p.z);
      }
    });
    ends.needsUpdate = true;
    const joints = this.joints.geometry.getAttribute("position") as THREE.BufferAttribute;
    for (let j = 0; j < this.rig.j; j++) {
      // a joint moves with its first body
      const b = this.rig.jointBodies[2 * j];
      motion.multiplyMatrices(this.skeletonBones[b].matrixWorld, inverse.copy(this.rest[b]).invert());
      p.fromArray(this.rig.jointPositions, 3 * j).applyMatrix4(motion);
      joints.setXYZ(j, p.x, p.y, p.z);
    }
    joints.needsUpdate = true;
  }

  /** The skin's ripple for the surface's filter φ (k): morph target ν weighs φ_ν − 1 (null:
   * none). */
  ripple(phi: ArrayLike<number> | null): void {
    for (const mesh of [this.skinned, this.skinnedLook]) {
      const influences = mesh?.morphTargetInfluences;
      if (!influences) continue;
      for (let nu = 0; nu < influences.length; nu++) influences[nu] = phi ? phi[nu] - 1 : 0;
    }
  }

  /** The LBS positions (n*3, file units) of the last pose and ripple, by three.js's own
   * morphing and skinning (`SkinnedMesh.getVertexPosition`, the CPU twin of its shader). */
  lbsPositions(): Float32Array {
    this.skinned.skeleton.update();
    const out = new Float32Array(3 * this.rig.n), v = new THREE.Vector3();
    for (let i = 0; i < this.rig.n; i++) this.skinned.getVertexPosition(i, v).toArray(out, 3 * i);
    return out;
  }

  /** The joint nearest to a point of the view (normalised device coordinates), within
   * `radius`; −1 if none. */
  nearestJoint(x: number, y: number, camera: THREE.Camera, radius = 0.06): number {
    const joints = this.joints.geometry.getAttribute("position") as THREE.BufferAttribute;
    const p = new THREE.Vector3();
    let best = -1, bestDistance = radius;
    for (let j = 0; j < this.rig.j; j++) {
      p.fromBufferAttribute(joints, j).applyMatrix4(this.group.matrix).project(camera);
      const distance = Math.hypot(p.x - x, p.y - y);
      if (distance < bestDistance) { best = j; bestDistance = distance; }
    }
    return best;
  }

  dispose(): void {
    this.group.removeFromParent();
    this.skinned.geometry.dispose();
    this.lbsMaterial.dispose();
    if (this.skinnedLook) {
      this.skinnedLook.geometry.dispose();
      for (const material of this.skinnedLook.material as THREE.Material[]) material.dispose();
    }
    this.skinned.skeleton.dispose();
    for (const object of [this.bones, this.joints, this.picked]) {
      object.geometry.dispose();
      (object.material as THREE.Material).dispose();
    }
  }
}
