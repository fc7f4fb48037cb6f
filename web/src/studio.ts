// The studio every model is shown in (docs/design.md#rendering): a backdrop gradient per view, a
// soft contact shadow under the model, and framing — a camera that makes the model fill its
// view, whatever the view's shape, from the model's own vertices.
import * as THREE from "three";
import type { Basis } from "./bundle";
import { BACKDROP_FRAGMENT, BACKDROP_VERTEX, SHADOW_FRAGMENT, SHADOW_VERTEX } from "./shaders";

/** The direction the cameras look from at first: front, a little right and above. */
export const VIEW_DIRECTION = new THREE.Vector3(0.42, 0.28, 1).normalize();
/** Room left around the model beyond the poses framed (its motion between them). */
const MOTION_MARGIN = 1.08;

export class Studio {
  readonly backdrop: THREE.Mesh;
  readonly shadow: THREE.Mesh;
  private readonly backdropMaterial: THREE.RawShaderMaterial;
  private readonly shadowMaterial: THREE.RawShaderMaterial;

  constructor() {
    this.backdropMaterial = new THREE.RawShaderMaterial({
      glslVersion: THREE.GLSL3, vertexShader: BACKDROP_VERTEX, fragmentShader: BACKDROP_FRAGMENT,
      uniforms: { top: { value: new THREE.Color(0x2b303b) }, bottom: { value:
        new THREE.Color(0x121418) }, aspect: { value: 1 } },
      depthTest: false, depthWrite: false,
    });
    this.backdrop = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), this.backdropMaterial);
    this.backdrop.frustumCulled = false;
    this.backdrop.renderOrder = -2;
    this.shadowMaterial = new THREE.RawShaderMaterial({
      glslVersion: THREE.GLSL3, vertexShader: SHADOW_VERTEX, fragmentShader: SHADOW_FRAGMENT,
      uniforms: { strength: { value: 0.55 } }, transparent: true, depthWrite: false,
    });
    this.shadow = new THREE.Mesh(new THREE.PlaneGeometry(2, 2).rotateX(-Math.PI / 2),
      this.shadowMaterial);
    this.shadow.renderOrder = -1;
  }

  /** Put the shadow under a (normalised, centred) model: on the plane of its lowest point,
   * as wide as its footprint. */
  placeShadow(basis: Basis): void {
    const box = new THREE.Box3().setFromBufferAttribute(
      new THREE.BufferAttribute(basis.vertices, 3));
    const size = box.getSize(new THREE.Vector3());
    this.shadow.position.set((box.min.x + box.max.x) / 2, box.min.y - 0.01 * size.y,
      (box.min.z + box.max.z) / 2);
    this.shadow.scale.set(0.62 * size.x + 0.05, 1, 0.62 * size.z + 0.05);
  }

  /** Before drawing a view of this aspect (width / height). */
  setAspect(aspect: number): void { this.backdropMaterial.uniforms.aspect.value = aspect; }

  dispose(): void {
    this.backdrop.geometry.dispose();
    this.shadow.geometry.dispose();
    this.backdropMaterial.dispose();
    this.shadowMaterial.dispose();
  }
}

/** Points of the model seen along `direction`: for each its depth s toward the camera and its
 * position (x, y) across the view. */
export interface Silhouette { s: Float32Array; x: Float32Array; y: Float32Array; }

/** The view's axes for a camera looking along −direction, up as close to +y as it can. */
function axes(direction: THREE.Vector3): [THREE.Vector3, THREE.Vector3, THREE.Vector3] {
  const forward = direction.clone().normalize();
  const right = new THREE.Vector3(0, 1, 0).cross(forward).normalize();
  return [forward, right, forward.clone().cross(right)];
}

export function silhouette(points: Float32Array, direction: THREE.Vector3): Silhouette {
  const [forward, right, up] = axes(direction);
  const n = points.length / 3;
  const s = new Float32Array(n), x = new Float32Array(n), y = new Float32Array(n);
  for (let i = 0; i < n; i++) {
    const px = points[3 * i], py = points[3 * i + 1], pz = points[3 * i + 2];
    s[i] = px * forward.x + py * forward.y + pz * forward.z;
    x[i] = px * right.x + py * right.y + pz * right.z;
    y[i] = px * up.x + py * up.y + pz * up.z;
  }
  return { s, x, y };
}

/** The vertices that frame the model (of `shape`, the rest shape): the `share` of them that
 * reach farthest from the middle of the view, the ones its motion can push out of it. */
export function rim(shape: Silhouette, share: number): Int32Array {
  const n = shape.x.length;
  const [cx, cy] = middle([shape]);
  const reach = new Float32Array(n);
  for (let i = 0; i < n; i++) {
    reach[i] = shape.s[i] + Math.max(Math.abs(shape.x[i] - cx), Math.abs(shape.y[i] - cy));
  }
  const order = Array.from({ length: n }, (_, i) => i).sort((a, b) => reach[b] - reach[a]);
  return Int32Array.from(order.slice(0, Math.max(1, Math.ceil(share * n))));
}

function middle(shapes: Silhouette[]): [number, number] {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const shape of shapes) {
    for (let i = 0; i < shape.x.length; i++) {
      x0 = Math.min(x0, shape.x[i]); x1 = Math.max(x1, shape.x[i]);
      y0 = Math.min(y0, shape.y[i]); y1 = Math.max(y1, shape.y[i]);
    }
  }
  return [(x0 + x1) / 2, (y0 + y1) / 2];
}

/** Where a camera of vertical field of view `fovDegrees` looking along −direction must stand so
 * that every point of the shapes (the rest shape, and the rim in the poses the music gives it)
 * fits a view of this aspect with MOTION_MARGIN to spare: the target (the middle of the
 * silhouette) and the distance from it. */
export function framing(shapes: Silhouette[], direction: THREE.Vector3, fovDegrees: number,
                        aspect: number): { target: THREE.Vector3; distance: number } {
  const [, right, up] = axes(direction);
  const [cx, cy] = middle(shapes);
  const tanV = Math.tan(THREE.MathUtils.degToRad(fovDegrees) / 2) / MOTION_MARGIN;
  const tanH = tanV * aspect;
  let distance = 0;
  for (const shape of shapes) {
    for (let i = 0; i < shape.x.length; i++) {
      const reach = Math.max(Math.abs(shape.y[i] - cy) / tanV, Math.abs(shape.x[i] - cx) / tanH);
      distance = Math.max(distance, shape.s[i] + reach);
    }
  }
  return { target: right.multiplyScalar(cx).add(up.multiplyScalar(cy)), distance };
}
