// The glTF export seen in three.js: the scene's .glb parsed by GLTFLoader,
// its lights (KHR_lights_punctual) or a default one, its camera as the
// start view, and orbit controls. Drawn only when something changes.
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

// A light exported from a scene file carries its colour and the distance
// at which that colour is what it gives (extras.sf). Its candela are for a
// renderer with exposure; here the light gives at that distance the
// irradiance that lets a white diffuse surface show the colour itself.
function matchSceneLight(light) {
  const sf = light.userData?.sf ?? light.parent?.userData?.sf;
  if (!sf?.referenceDistance || !sf.colour) return;
  const brightest = Math.max(...sf.colour);
  light.intensity = Math.PI * brightest * sf.referenceDistance ** 2;
}

export class GltfView {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    container.append(this.renderer.domElement);
    this.camera = new THREE.PerspectiveCamera(45, 4 / 3, 0.01, 1000);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.draw());
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x1b1e23);
    this.loader = new GLTFLoader();
    this.hasView = false;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const width = this.container.clientWidth || 1;
    const height = this.container.clientHeight || 1;
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  draw() {
    this.renderer.render(this.scene, this.camera);
  }

  // Shows a .glb (an ArrayBuffer). The first one sets the view from its
  // camera; later ones keep where the user has orbited to.
  show(glb) {
    return new Promise((resolve, reject) => {
      this.loader.parse(glb, '', (gltf) => {
        this.setScene(gltf);
        resolve();
      }, reject);
    });
  }

  setScene(gltf) {
    const scene = gltf.scene;
    scene.updateMatrixWorld(true);
    let lights = 0;
    scene.traverse((node) => {
      if (!node.isLight) return;
      lights += 1;
      matchSceneLight(node);
    });
    const shown = new THREE.Scene();
    shown.background = this.scene.background;
    shown.add(scene);
    shown.add(new THREE.HemisphereLight(0xffffff, 0x444444, 0.6));
    if (lights === 0) {
      const light = new THREE.DirectionalLight(0xffffff, 2);
      light.position.set(5, 8, 5);
      shown.add(light);
    }
    this.disposeScene(this.scene);
    this.scene = shown;
    if (!this.hasView) this.setView(gltf, scene);
    this.draw();
  }

  setView(gltf, scene) {
    const box = new THREE.Box3().setFromObject(scene);
    const center = box.isEmpty() ? new THREE.Vector3() : box.getCenter(new THREE.Vector3());
    const source = gltf.cameras?.[0];
    if (source) {
      source.updateMatrixWorld(true);
      source.matrixWorld.decompose(this.camera.position, this.camera.quaternion, new THREE.Vector3());
      if (source.isPerspectiveCamera) this.camera.fov = source.fov;
      // Orbit around the point the camera looks at, as far as the scene's centre.
      const forward = new THREE.Vector3(0, 0, -1).applyQuaternion(this.camera.quaternion);
      const distance = Math.max(0.1, center.clone().sub(this.camera.position).dot(forward));
      this.controls.target.copy(this.camera.position).addScaledVector(forward, distance);
    } else {
      const size = box.isEmpty() ? 5 : box.getSize(new THREE.Vector3()).length();
      this.camera.position.copy(center).add(new THREE.Vector3(size, size * 0.6, size));
      this.controls.target.copy(center);
    }
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.hasView = true;
  }

  disposeScene(scene) {
    scene.traverse((node) => {
      node.geometry?.dispose();
      const materials = Array.isArray(node.material) ? node.material : node.material ? [node.material] : [];
      for (const material of materials) material.dispose();
    });
  }
}
