// The stage both pages share, as tests/bench/scenes/peer_*.json set it: black background, a
// camera at 3 m with a 45° vertical field of view, 1 directional + 3 point lights (W/sr = Φ/4π).
import * as THREE from "three";

export function peerStage(width, height) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0, 0, 0);
  const camera = new THREE.PerspectiveCamera(45, width / height, 0.05, 100);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);
  const sun = new THREE.DirectionalLight(0xffffff, 2.0);  // irradiance 2 W/m², from (0.4, 0.7, 0.6)
  sun.position.set(0.4, 0.7, 0.6);
  scene.add(sun);
  for (const [position, power, color] of [[[2, 2, 2], 100, [1, 0.95, 0.9]], [[-2.5, 0.5, 1.5], 40, [0.8, 0.85, 1]],
                                           [[0, 1.5, -2.5], 60, [1, 1, 1]]]) {
    const light = new THREE.PointLight(new THREE.Color(...color), power / (4 * Math.PI), 0, 2);  // I = Φ/4π, 1/d²
    light.position.set(...position);
    scene.add(light);
  }
  return {scene, camera};
}
