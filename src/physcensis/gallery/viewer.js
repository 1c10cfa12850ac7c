"use strict";
// The report's 3-D viewer: one scene's glb drawn with three.js (the PhyscensisThree bundle before this script), orbit,
// zoom and pan with OrbitControls, and picking: a click (not a drag) on an object names it. It shows no text itself:
// the page's dialog (dialog.js) shows what was picked, from the page's own data, as text.
(function () {
  const THREE = globalThis.PhyscensisThree;
  const CLICK_SLOP_PX = 4; // a press that moves further is an orbit or a pan, not a pick
  const VIEW_FROM = new THREE.Vector3(0.35, 0.75, 1).normalize(); // above the front of the table (glTF is y-up)

  // A glb could name other files (buffers, images by URL): none is loaded, the viewer draws only what it holds.
  function ownDataOnly(url) {
    return url.startsWith("blob:") ? url : "data:,";
  }

  function parse(buffer) {
    const manager = new THREE.LoadingManager();
    manager.setURLModifier(ownDataOnly);
    return new Promise((resolve, reject) => new THREE.GLTFLoader(manager).parse(buffer, "", resolve, reject));
  }

  // The nodes named by an object id (export/glb.py names each object's node by its id); three.js keeps a node's
  // name from the file in userData.name, its own `name` being made unique and safe for animation paths.
  function objectNodes(root, ids) {
    const nodes = new Map();
    root.traverse((node) => {
      const name = node.userData ? node.userData.name : undefined;
      if (typeof name === "string" && ids.has(name) && !nodes.has(name)) nodes.set(name, node);
    });
    return nodes;
  }

  function frame(camera, controls, nodes) {
    const box = new THREE.Box3();
    nodes.forEach((node) => box.expandByObject(node));
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 0.15);
    const distance = (1.15 * radius) / Math.sin((camera.fov * Math.PI) / 360);
    camera.position.copy(center).addScaledVector(VIEW_FROM, distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
  }

  function lights(scene) {
    scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f96, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(1, 3, 2);
    scene.add(sun);
  }

  function dispose(root) {
    root.traverse((node) => {
      if (node.geometry) node.geometry.dispose();
      const materials = Array.isArray(node.material) ? node.material : node.material ? [node.material] : [];
      materials.forEach((material) => material.dispose());
    });
  }

  // Draw the glb `buffer` (an ArrayBuffer) in `stage`; `ids` are the object ids to make pickable; `onPick(id)` is
  // called with the id clicked, or null for a click on nothing (or on the table). Resolves to the view's handle.
  async function show(stage, buffer, ids, onPick) {
    const gltf = await parse(buffer);
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    const canvas = renderer.domElement;
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xeef1f4);
    lights(scene);
    scene.add(gltf.scene);
    const objects = objectNodes(gltf.scene, new Set(ids));
    const owners = new Map(Array.from(objects, ([id, node]) => [node, id]));
    const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    const controls = new THREE.OrbitControls(camera, canvas);
    const raycaster = new THREE.Raycaster();
    let marker = null;
    let pending = 0;
    let pressed = null;

    function render() {
      pending = 0;
      renderer.render(scene, camera);
    }
    function requestRender() {
      if (!pending) pending = requestAnimationFrame(render);
    }
    function resize() {
      const width = Math.max(stage.clientWidth, 1);
      const height = Math.max(stage.clientHeight, 1);
      renderer.setSize(width, height);
      camera.aspect = width / height;
      camera.updateProjectionMatrix();
      render();
    }
    function owner(node) {
      for (let at = node; at; at = at.parent) if (owners.has(at)) return owners.get(at);
      return null;
    }
    // The object under a point of the page (client coordinates): the first surface hit, so the table hides what is
    // behind it; null for the table, the ground or nothing.
    function pickAt(x, y) {
      const rect = canvas.getBoundingClientRect();
      const pointer = new THREE.Vector2(((x - rect.left) / rect.width) * 2 - 1, 1 - ((y - rect.top) / rect.height) * 2);
      raycaster.setFromCamera(pointer, camera);
      const hit = raycaster.intersectObject(gltf.scene, true)[0];
      return hit ? owner(hit.object) : null;
    }
    function select(id) {
      if (marker) {
        scene.remove(marker);
        marker.dispose();
        marker = null;
      }
      if (id !== null && objects.has(id)) {
        marker = new THREE.BoxHelper(objects.get(id), 0x2a62b8);
        scene.add(marker);
      }
      requestRender();
      onPick(id !== null && objects.has(id) ? id : null);
    }
    function toClient(point) {
      const rect = canvas.getBoundingClientRect();
      const ndc = point.clone().project(camera);
      return { x: rect.left + ((ndc.x + 1) / 2) * rect.width, y: rect.top + ((1 - ndc.y) / 2) * rect.height };
    }
    // A point of the page where a click picks `id`, and would still a few pixels away (its centre when visible there,
    // else one of its vertices), or null when none is found: what a test clicks.
    function screenPoint(id) {
      const node = objects.get(id);
      if (!node) return null;
      const candidates = [new THREE.Box3().setFromObject(node).getCenter(new THREE.Vector3())];
      node.traverse((part) => {
        const position = part.isMesh ? part.geometry.attributes.position : null;
        if (!position) return;
        const step = Math.max(1, Math.floor(position.count / 200));
        for (let k = 0; k < position.count; k += step) {
          candidates.push(new THREE.Vector3().fromBufferAttribute(position, k).applyMatrix4(part.matrixWorld));
        }
      });
      const rect = canvas.getBoundingClientRect();
      const picks = (x, y) => x > rect.left && x < rect.right && y > rect.top && y < rect.bottom && pickAt(x, y) === id;
      for (const point of candidates) {
        const { x, y } = toClient(point);
        if ([0, 3, -3].every((dx) => [0, 3, -3].every((dy) => picks(x + dx, y + dy)))) return { x, y };
      }
      return null;
    }

    canvas.addEventListener("pointerdown", (event) => {
      pressed = event.button === 0 ? { x: event.clientX, y: event.clientY } : null;
    });
    canvas.addEventListener("pointerup", (event) => {
      if (!pressed || Math.hypot(event.clientX - pressed.x, event.clientY - pressed.y) > CLICK_SLOP_PX) return;
      pressed = null;
      select(pickAt(event.clientX, event.clientY));
    });
    controls.addEventListener("change", requestRender);
    stage.replaceChildren(canvas);
    const watcher = new ResizeObserver(resize);
    watcher.observe(stage);
    scene.updateMatrixWorld(true);
    frame(camera, controls, objects.size ? Array.from(objects.values()) : [gltf.scene]);
    resize();

    return {
      canvas,
      ids: () => Array.from(objects.keys()),
      nodeNames() {
        const names = [];
        gltf.scene.traverse((node) => {
          if (node.userData && typeof node.userData.name === "string") names.push(node.userData.name);
        });
        return names;
      },
      pickAt,
      screenPoint,
      select,
      close() {
        watcher.disconnect();
        if (pending) cancelAnimationFrame(pending);
        controls.dispose();
        dispose(scene);
        renderer.dispose();
        renderer.forceContextLoss();
        canvas.remove();
      },
    };
  }

  globalThis.PhyscensisViewer = { show };
})();
