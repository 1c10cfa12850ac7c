// What the report's 3-D viewer (../viewer.js) takes from three.js; esbuild bundles it into three-viewer.min.js,
// which sets the global PhyscensisThree (see README.md for the exact command and versions).
export {
  Box3,
  BoxHelper,
  Color,
  DirectionalLight,
  HemisphereLight,
  LoadingManager,
  PerspectiveCamera,
  Raycaster,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
} from "three";
export { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
export { OrbitControls } from "three/addons/controls/OrbitControls.js";
