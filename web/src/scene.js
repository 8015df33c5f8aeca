// The WebGL view of a trained model (three.js): the extracted mesh with the learned materials
// (per-vertex albedo, roughness and IoR → a physically based material), or the exported glTF
// (model.glb, as any glTF viewer reads it), a lat-long environment map as background and light,
// orbit controls. Used by the result viewer and the relight preview.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { PLYLoader } from 'three/addons/loaders/PLYLoader.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';
import { HDRLoader } from 'three/addons/loaders/HDRLoader.js';

/**
 * The rotation from phygap's world (up +Z or +Y) into three.js's (up +Y) under which phygap's
 * lat-long maps (row 0 = up; column φ looks along sinφ·r + cosφ·f) land where three.js's
 * equirectangular lookup expects them: f → −x, r → −z, up → +y.
 */
function worldToThree(worldUp) {
  const m = new THREE.Matrix4();
  if (worldUp[1] === 1) {
    // r = +X, f = −Z, u = +Y.
    m.set(0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1);
  } else {
    // r = +X, f = +Y, u = +Z.
    m.set(0, -1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0, 0, 0, 0, 1);
  }
  return m;
}

/** A material reading albedo from vertex colours and roughness and IoR from vertex attributes. */
function learnedMaterial() {
  const material = new THREE.MeshPhysicalMaterial({ vertexColors: true, metalness: 0, roughness: 1, ior: 1.5 });
  material.onBeforeCompile = (shader) => {
    shader.vertexShader = shader.vertexShader
      .replace('#include <common>', '#include <common>\nattribute float aRoughness;\nattribute float aIor;\nvarying float vRoughness;\nvarying float vIor;')
      .replace('#include <begin_vertex>', '#include <begin_vertex>\nvRoughness = aRoughness;\nvIor = aIor;');
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <common>', '#include <common>\nvarying float vRoughness;\nvarying float vIor;')
      .replace('#include <roughnessmap_fragment>', 'float roughnessFactor = vRoughness;')
      .replace(
        '#include <lights_physical_fragment>',
        THREE.ShaderChunk.lights_physical_fragment.replace('material.ior = ior;', 'material.ior = vIor;'),
      );
  };
  return material;
}

/** Parses a PLY from the material-mesh route into a geometry with aRoughness and aIor. */
export function parseMaterialMesh(buffer) {
  const loader = new PLYLoader();
  loader.setCustomPropertyNameMapping({ aRoughness: ['roughness'], aIor: ['ior'] });
  const geometry = loader.parse(buffer);
  if (!geometry.getAttribute('normal')) geometry.computeVertexNormals();
  return geometry;
}

/**
 * Parses a glTF binary (the export's model.glb) into its scene. Its node already turns phygap's
 * world into three.js's frame the way worldToThree does, so it goes straight into the scene.
 */
export function parseGltf(buffer) {
  return new Promise((resolve, reject) => {
    new GLTFLoader().parse(buffer, '', (gltf) => resolve(gltf.scene), reject);
  });
}

/** Frees the geometries, materials and textures under `object`. */
function disposeTree(object) {
  object.traverse((node) => {
    if (node.geometry) node.geometry.dispose();
    const materials = node.material ? [].concat(node.material) : [];
    for (const material of materials) {
      for (const value of Object.values(material)) if (value && value.isTexture) value.dispose();
      material.dispose();
    }
  });
}

/** Parses an environment map's bytes (OpenEXR or Radiance HDR, told apart by magic bytes). */
export function parseEnvironment(buffer) {
  const head = new Uint8Array(buffer, 0, 4);
  const isExr = head[0] === 0x76 && head[1] === 0x2f && head[2] === 0x31 && head[3] === 0x01;
  const loader = isExr ? new EXRLoader() : new HDRLoader();
  loader.setDataType(THREE.FloatType);
  const data = loader.parse(buffer);
  const texture = new THREE.DataTexture(data.data, data.width, data.height, THREE.RGBAFormat, data.type);
  if (data.format !== undefined) texture.format = data.format;
  texture.colorSpace = THREE.LinearSRGBColorSpace;
  texture.flipY = !!data.flipY;
  texture.mapping = THREE.EquirectangularReflectionMapping;
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearFilter;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
}

/** A live view on `canvas`. */
export class ModelView {
  constructor(canvas) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x20232a);
    this.world = new THREE.Group();
    this.world.matrixAutoUpdate = false;
    this.scene.add(this.world);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
    this.camera.position.set(0, 0.6, 3.2);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = true;
    this.controls.addEventListener('change', () => this.render());
    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(canvas);
    this.running = true;
    const loop = () => {
      if (!this.running) return;
      if (this.controls.update()) this.render();
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  }

  /** Matches the drawing buffer to the canvas's CSS size. */
  fit() {
    const width = this.canvas.clientWidth;
    const height = this.canvas.clientHeight;
    if (!width || !height) return;
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  setWorldUp(worldUp) {
    this.world.matrix.copy(worldToThree(worldUp));
    this.world.updateMatrixWorld(true);
  }

  /** Shows the mesh and points the camera at it. */
  setMesh(geometry) {
    if (this.mesh) {
      this.world.remove(this.mesh);
      this.mesh.geometry.dispose();
    }
    this.mesh = new THREE.Mesh(geometry, learnedMaterial());
    this.world.add(this.mesh);
    this.world.updateMatrixWorld(true);
    const sphere = new THREE.Box3().setFromObject(this.mesh).getBoundingSphere(new THREE.Sphere());
    const distance = (sphere.radius / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2))) * 1.15;
    this.controls.target.copy(sphere.center);
    this.camera.position.copy(sphere.center).add(new THREE.Vector3(1, 0.45, 1).normalize().multiplyScalar(distance));
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.render();
  }

  /** Adds the glTF scene (parseGltf) beside the material mesh, hidden until showGltf(true). */
  setGltf(object) {
    if (this.gltf) {
      this.scene.remove(this.gltf);
      disposeTree(this.gltf);
    }
    this.gltf = object;
    object.visible = false;
    this.scene.add(object);
  }

  /** Shows the glTF (true) or the material mesh (false); the camera stays where it is. */
  showGltf(on) {
    if (this.gltf) this.gltf.visible = on;
    if (this.mesh) this.mesh.visible = !on || !this.gltf;
    this.render();
  }

  /** The environment as background and light. */
  setEnvironment(texture) {
    if (this.environment) this.environment.dispose();
    this.environment = texture;
    this.scene.background = texture;
    this.scene.environment = texture;
    this.render();
  }

  /** Turns the environment about the up axis (right-handed, as the relight job's rotate_deg). */
  setRotation(degrees) {
    const radians = THREE.MathUtils.degToRad(degrees);
    this.scene.backgroundRotation.set(0, radians, 0);
    this.scene.environmentRotation.set(0, radians, 0);
    this.render();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  dispose() {
    this.running = false;
    if (this.gltf) disposeTree(this.gltf);
    this.resize.disconnect();
    this.controls.dispose();
    this.renderer.dispose();
  }
}
