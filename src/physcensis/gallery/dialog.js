"use strict";
// The 3-D view dialog. A card's "3-D" button (page.js) sends its card here. The viewer's script (three.js and
// viewer.js) runs only at the first press, inserted as an inline script the page's policy admits by its hash; the
// scene's glb comes from its block in the page (--embed) or by its relative URL (a page served by
// `physcensis report --serve`). What a click picks is shown from the page's data, as text only.
(function () {
  const byId = (id) => document.getElementById(id);
  const dialog = byId("viewer");
  const stage = byId("viewer-stage");
  const info = byId("viewer-info");
  const message = byId("viewer-message");
  const title = byId("viewer-title");
  const FROM_A_FILE =
    "A page opened from a file cannot load the scene's 3-D file (the browser forbids it). To turn the scenes " +
    "around in 3-D, make the report with `physcensis report FOLDER --embed` (the scenes inside the page) or serve " +
    "it with `physcensis report FOLDER --serve` and open the address it prints.";
  const FETCH_TIMEOUT_MS = 120000;
  const parsed = new Promise((resolve) => document.addEventListener("DOMContentLoaded", resolve, { once: true }));
  let view = null; // the open viewer's handle
  let opening = 0; // counts the openings: a load that ends after the dialog was closed or opened again is dropped

  function element(tag, className, text) {
    const node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined) node.textContent = text;
    return node;
  }

  function setState(state, text) {
    dialog.dataset.state = state;
    message.textContent = text || "";
    message.hidden = !text;
  }

  // The viewer's script, run once: JSON text in the page until now, so a page of many scenes opens without it.
  function viewer() {
    if (!globalThis.PhyscensisViewer) {
      const script = document.createElement("script");
      script.textContent = JSON.parse(byId("viewer-code").textContent);
      document.head.appendChild(script); // an inline script runs as it is inserted
    }
    if (!globalThis.PhyscensisViewer) throw new Error("the browser did not run the viewer's script");
    return globalThis.PhyscensisViewer;
  }

  function fromBase64(text) {
    if (typeof Uint8Array.fromBase64 === "function") return Uint8Array.fromBase64(text);
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let k = 0; k < binary.length; k += 1) bytes[k] = binary.charCodeAt(k);
    return bytes;
  }

  async function glbBytes(source) {
    if (source.block) return fromBase64(byId(source.block).textContent.trim()).buffer;
    const signal = AbortSignal.timeout(FETCH_TIMEOUT_MS);
    const response = await fetch(source.url, { credentials: "same-origin", cache: "no-store", signal });
    if (!response.ok) throw new Error(source.path + ": the server answered " + response.status);
    return response.arrayBuffer();
  }

  function isGlb(buffer) {
    const head = new Uint8Array(buffer, 0, Math.min(4, buffer.byteLength));
    return String.fromCharCode.apply(null, head) === "glTF";
  }

  function formatNumber(value, unit) {
    if (value === null || value === undefined) return "–";
    return String(Number.parseFloat(value.toPrecision(4))) + (unit ? " " + unit : "");
  }

  function fact(table, name, value) {
    const row = element("tr");
    row.appendChild(element("th", "", name));
    row.appendChild(element("td", "", value));
    table.appendChild(row);
  }

  function showObject(objects, id) {
    info.replaceChildren();
    info.dataset.object = id === null ? "" : id;
    const entry = id === null ? undefined : objects.get(id);
    if (!entry) {
      info.appendChild(element("p", "viewer-hint", "Click an object to see what it is."));
      return;
    }
    info.appendChild(element("h3", "viewer-object", entry.id));
    if (entry.description) info.appendChild(element("p", "viewer-description", entry.description));
    const table = element("table", "viewer-facts");
    fact(table, "asset", entry.asset || "–");
    fact(table, "category", entry.category || "–");
    fact(table, "mass", formatNumber(entry.mass, "kg"));
    fact(table, "friction", formatNumber(entry.friction));
    fact(table, "p_fail", entry.p_fail === null ? "not measured" : formatNumber(entry.p_fail));
    info.appendChild(table);
    info.appendChild(element("p", "viewer-label", "placed by"));
    const list = element("ul", "viewer-predicates");
    entry.predicates.forEach((line) => list.appendChild(element("li", "", line)));
    if (entry.predicates.length === 0) list.appendChild(element("li", "", "(no statement recorded)"));
    info.appendChild(list);
  }

  function closeView() {
    opening += 1;
    if (view) view.close();
    view = null;
    globalThis.physcensisViewer = null;
    stage.replaceChildren();
  }

  async function open(source) {
    closeView();
    const ticket = opening;
    const objects = new Map(source.card.objects.map((entry) => [entry.id, entry]));
    title.textContent = source.card.prompt || source.card.scene_dir || "(no prompt)";
    info.replaceChildren();
    if (!dialog.open) dialog.showModal();
    if (!source.block && location.protocol === "file:") {
      setState("unavailable", FROM_A_FILE);
      return;
    }
    setState("loading", "loading " + source.path + " …");
    try {
      if (document.readyState === "loading") await parsed; // the viewer's code and the glbs follow the cards
      if (ticket !== opening) return;
      const show = viewer().show;
      const buffer = await glbBytes(source);
      if (ticket !== opening) return;
      if (!isGlb(buffer)) throw new Error(source.path + " is not a glb file");
      const handle = await show(stage, buffer, Array.from(objects.keys()), (id) => showObject(objects, id));
      if (ticket !== opening) return handle.close();
      view = handle;
      globalThis.physcensisViewer = handle; // the open view, for tests and the browser's console
      showObject(objects, null);
      setState("ready", "");
    } catch (error) {
      if (ticket === opening) setState("failed", "The 3-D view could not be shown: " + (error && error.message));
    }
  }

  byId("viewer-close").addEventListener("click", () => dialog.close());
  dialog.addEventListener("close", closeView);
  document.addEventListener("physcensis-view3d", (event) => open(event.detail));
})();
