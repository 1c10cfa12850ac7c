"use strict";
// The gallery's behaviour: cards built from the embedded JSON (text only, never parsed as HTML), sorting and filters.
(function () {
  const data = JSON.parse(document.getElementById("gallery-data").textContent);
  const byId = (id) => document.getElementById(id);
  const controls = {
    text: byId("filter-text"),
    method: byId("filter-method"),
    failures: byId("filter-failures"),
    group: byId("group-prompt"),
    rangeMetric: byId("range-metric"),
    rangeMin: byId("range-min"),
    rangeMax: byId("range-max"),
    sortKey: byId("sort-key"),
    sortOrder: byId("sort-order"),
    reset: byId("reset"),
  };
  const grid = byId("cards");
  const count = byId("count");
  const empty = byId("empty");
  const summary = byId("summary");
  const sections = new Map(); // group key -> { node, row, count }: the per-prompt rows, made when first needed

  function element(tag, className, text) {
    const node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined) node.textContent = text;
    return node;
  }

  function option(select, value, label) {
    const node = element("option", "", label);
    node.value = value;
    select.appendChild(node);
  }

  function formatNumber(value) {
    if (value === null || value === undefined) return "–";
    if (Number.isInteger(value)) return String(value);
    return String(Number.parseFloat(value.toPrecision(4)));
  }

  function imageSource(path) {
    if (!path) return null;
    return Object.prototype.hasOwnProperty.call(data.images, path) ? data.images[path] : data.urls[path];
  }

  function imageTile(card, key, label) {
    const source = imageSource(card[key]);
    if (!source) return null;
    const link = element("a", "tile");
    link.href = source;
    link.target = "_blank";
    link.rel = "noopener";
    const image = element("img");
    image.src = source;
    image.loading = "lazy";
    image.alt = label + " of: " + card.prompt;
    link.appendChild(image);
    link.appendChild(element("span", "caption", label));
    return link;
  }

  function imagesBlock(card) {
    const block = element("div", "images");
    const tiles = [imageTile(card, "render", "render"), imageTile(card, "layout", "layout")].filter(Boolean);
    if (tiles.length === 0) block.appendChild(element("p", "noimage", "no render"));
    tiles.forEach((tile) => block.appendChild(tile));
    if (tiles.length === 1) block.classList.add("single");
    return block;
  }

  function headerBlock(card) {
    const header = element("header");
    header.appendChild(element("p", "prompt", card.prompt || "(no prompt)"));
    const tags = element("div", "tags");
    tags.appendChild(element("span", "tag method", card.method));
    if (card.seed !== null) tags.appendChild(element("span", "tag", "seed " + card.seed));
    if (card.ok !== null) tags.appendChild(element("span", card.ok ? "tag ok" : "tag bad", card.ok ? "ok" : "failed"));
    if (card.prompt_id && card.prompt_id !== card.prompt) tags.appendChild(element("span", "tag id", card.prompt_id));
    header.appendChild(tags);
    return header;
  }

  function metricsBlock(card) {
    const table = element("table", "metrics");
    const rows = {};
    data.metrics.forEach((name) => {
      if (!Object.prototype.hasOwnProperty.call(card.metrics, name)) return;
      const row = element("tr");
      row.appendChild(element("th", "", name));
      row.appendChild(element("td", "", formatNumber(card.metrics[name])));
      rows[name] = row;
      table.appendChild(row);
    });
    return { table, rows };
  }

  function failuresBlock(card) {
    if (card.failures.length === 0) return element("p", "nofailures", "no failures");
    const details = element("details", "failures");
    details.open = card.failures.length <= 3;
    const noun = card.failures.length === 1 ? " failure" : " failures";
    details.appendChild(element("summary", "", card.failures.length + noun));
    const list = element("ul");
    card.failures.forEach((text) => list.appendChild(element("li", "", text)));
    details.appendChild(list);
    return details;
  }

  function own(map, key) {
    return Object.prototype.hasOwnProperty.call(map, key) ? map[key] : null;
  }

  // The "3-D" button of a card with a glb: the dialog (dialog.js) loads the viewer and the glb only when pressed.
  function viewButton(card) {
    const button = element("button", "view3d", "3-D");
    button.type = "button";
    button.title = "turn the scene around in 3-D";
    button.addEventListener("click", () => {
      const source = { card, path: card.glb, url: own(data.urls, card.glb), block: own(data.glbs, card.glb) };
      document.dispatchEvent(new CustomEvent("physcensis-view3d", { detail: source }));
    });
    return button;
  }

  function footerBlock(card) {
    const footer = element("footer");
    if (card.scene_dir && data.urls[card.scene_dir]) {
      const link = element("a", "", card.scene_dir);
      link.href = data.urls[card.scene_dir];
      footer.appendChild(link);
    } else {
      footer.appendChild(element("span", "", card.scene_dir || "(no scene folder)"));
    }
    if (card.glb) footer.appendChild(viewButton(card));
    return footer;
  }

  function buildCard(card, index) {
    const article = element("article", "card");
    article.dataset.index = String(index);
    const metrics = metricsBlock(card);
    [headerBlock(card), imagesBlock(card), metrics.table, failuresBlock(card), footerBlock(card)].forEach((part) =>
      article.appendChild(part),
    );
    return { card, index, article, metricRows: metrics.rows, search: (card.prompt + "\n" + card.prompt_id).toLowerCase() };
  }

  const entries = data.cards.map(buildCard);

  function fillControls() {
    data.methods.forEach((method) => option(controls.method, method, method));
    data.metrics.forEach((name) => {
      option(controls.sortKey, "m:" + name, name);
      option(controls.rangeMetric, name, name);
    });
    controls.method.disabled = data.methods.length < 2;
    controls.group.checked = data.group_by_prompt;
  }

  function sortValue(entry, key) {
    if (key === "index") return entry.index;
    if (key === "seed") return entry.card.seed;
    if (key === "prompt" || key === "method") return entry.card[key].toLowerCase();
    const value = entry.card.metrics[key.slice(2)];
    return value === undefined ? null : value;
  }

  function compareEntries(key, descending) {
    return (a, b) => {
      const x = sortValue(a, key);
      const y = sortValue(b, key);
      if (x === null || y === null) {
        if (x === y) return a.index - b.index;
        return x === null ? 1 : -1; // missing values last, whichever the direction
      }
      const order = x < y ? -1 : x > y ? 1 : 0;
      return (descending ? -order : order) || a.index - b.index;
    };
  }

  function numberOrNull(input) {
    const text = input.value.trim();
    if (text === "") return null;
    const value = Number(text);
    return Number.isFinite(value) ? value : null;
  }

  function inRange(entry) {
    const name = controls.rangeMetric.value;
    const low = numberOrNull(controls.rangeMin);
    const high = numberOrNull(controls.rangeMax);
    if (!name || (low === null && high === null)) return true;
    const value = entry.card.metrics[name];
    if (value === null || value === undefined) return false;
    return (low === null || value >= low) && (high === null || value <= high);
  }

  function hasFailures(entry) {
    return entry.card.failures.length > 0 || entry.card.ok === false;
  }

  function matches(entry) {
    const text = controls.text.value.trim().toLowerCase();
    if (text && !entry.search.includes(text)) return false;
    if (controls.method.value && entry.card.method !== controls.method.value) return false;
    if (controls.failures.checked && !hasFailures(entry)) return false;
    return inRange(entry);
  }

  function markSortedMetric(entry, key) {
    Object.entries(entry.metricRows).forEach(([name, row]) => row.classList.toggle("sorted", key === "m:" + name));
  }

  function meanAndStd(values) {
    const mean = values.reduce((sum, v) => sum + v, 0) / values.length;
    const variance = values.reduce((sum, v) => sum + (v - mean) * (v - mean), 0) / values.length;
    return formatNumber(mean) + " ± " + formatNumber(Math.sqrt(variance));
  }

  function summaryRow(cells, header) {
    const row = element("tr");
    cells.forEach((text) => row.appendChild(element(header ? "th" : "td", "", text)));
    return row;
  }

  // Per method, over the cards shown: how many, how many with failures, and the sorted metric's mean ± std.
  function renderSummary(shown, key) {
    const metric = key.startsWith("m:") ? key.slice(2) : null;
    summary.replaceChildren(summaryRow(["method", "scenes", "with failures"].concat(metric ? [metric + " (mean ± std)"] : []), true));
    data.methods.forEach((method) => {
      const mine = shown.filter((entry) => entry.card.method === method);
      if (mine.length === 0) return;
      const failed = mine.filter(hasFailures).length;
      const cells = [method, String(mine.length), String(failed)];
      if (metric) {
        const values = mine.map((entry) => entry.card.metrics[metric]).filter((v) => v !== null && v !== undefined);
        cells.push(values.length ? meanAndStd(values) : "–");
      }
      summary.appendChild(summaryRow(cells, false));
    });
  }

  function groupKey(card) {
    return card.prompt || card.prompt_id || "";
  }

  function section(key) {
    if (!sections.has(key)) {
      const node = element("section", "group");
      const title = element("h2");
      title.appendChild(element("span", "group-prompt", key || "(no prompt)"));
      const count = element("span", "group-count");
      title.appendChild(count);
      const row = element("div", "group-row");
      node.appendChild(title);
      node.appendChild(row);
      sections.set(key, { node, row, count });
    }
    return sections.get(key);
  }

  // Grouped: one row per prompt, its scenes side by side in the sorted order; the rows in the order of their first
  // scene. Appending an attached node moves it, so the grid (or a row) takes the sorted order.
  function place(ordered) {
    grid.classList.toggle("grouped", controls.group.checked);
    if (!controls.group.checked) {
      ordered.forEach((entry) => grid.appendChild(entry.article));
      sections.forEach((part) => part.node.remove());
      return;
    }
    const members = new Map();
    ordered.forEach((entry) => {
      const key = groupKey(entry.card);
      if (!members.has(key)) members.set(key, []);
      members.get(key).push(entry);
    });
    members.forEach((group, key) => {
      const part = section(key);
      group.forEach((entry) => part.row.appendChild(entry.article));
      const visible = group.filter((entry) => !entry.article.hidden).length;
      part.count.textContent = visible + (visible === 1 ? " scene" : " scenes");
      part.node.hidden = visible === 0;
      grid.appendChild(part.node);
    });
  }

  function update() {
    const key = controls.sortKey.value;
    const descending = controls.sortOrder.value === "desc";
    const ordered = entries.slice().sort(compareEntries(key, descending));
    const shown = [];
    ordered.forEach((entry) => {
      const visible = matches(entry);
      entry.article.hidden = !visible;
      if (visible) shown.push(entry);
      markSortedMetric(entry, key);
    });
    place(ordered);
    count.textContent =
      "showing " + shown.length + " of " + entries.length + (entries.length === 1 ? " scene" : " scenes");
    empty.hidden = shown.length !== 0;
    renderSummary(shown, key);
  }

  function reset() {
    controls.text.value = "";
    controls.method.value = "";
    controls.failures.checked = false;
    controls.group.checked = data.group_by_prompt;
    controls.rangeMetric.value = "";
    controls.rangeMin.value = "";
    controls.rangeMax.value = "";
    controls.sortKey.value = "index";
    controls.sortOrder.value = "asc";
    update();
  }

  fillControls();
  [controls.text, controls.rangeMin, controls.rangeMax].forEach((input) => input.addEventListener("input", update));
  [controls.method, controls.failures, controls.group, controls.rangeMetric, controls.sortKey, controls.sortOrder].forEach((input) =>
    input.addEventListener("change", update),
  );
  controls.reset.addEventListener("click", reset);
  update();
  document.body.dataset.ready = "true";
  performance.mark("physcensis-cards"); // when the cards were shown (bench/report_open.py reads it)
})();
