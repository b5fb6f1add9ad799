// The page of `lab serve`: the panel is built from the lab's parameter
// declaration (the same one the window's panel reads), every change goes to
// the server over a WebSocket as a small JSON message, and frames come back
// as a JSON "frame" message followed by the image (JPEG, or PNG on request).
// window.labServe exposes the state, for tests.
"use strict";

const $ = (id) => document.getElementById(id);
const canvas = $("frame");
const context2d = canvas.getContext("2d");
const state = window.labServe = {
  lab: null, socket: null, frames: 0, meta: null, pendingMeta: null, lastError: "",
  acked: 0, unanswered: 0, problems: null, nextId: 1, playing: false, editing: null, send: null,
};

function send(message) {
  if (!state.socket || state.socket.readyState !== WebSocket.OPEN) return 0;
  message.id = state.nextId++;
  state.unanswered += 1;
  state.socket.send(JSON.stringify(message));
  return message.id;
}

state.send = send;

function setStatus(text, isError) {
  $("status").textContent = text;
  $("status").classList.toggle("error", !!isError);
}

// --- the panel, from the declaration ------------------------------------

function formatNumber(value, param) {
  if (param.type === "int") return String(Math.round(value));
  return Number(value).toPrecision(4).replace(/\.?0+$/, "");
}

function control(param) {
  const box = document.createElement("div");
  box.className = "param";
  box.dataset.name = param.name;
  const label = document.createElement("label");
  const name = document.createElement("span");
  name.textContent = param.name + (param.key ? " " : "");
  if (param.key) {
    const key = document.createElement("span");
    key.className = "key";
    key.textContent = param.key;
    name.appendChild(key);
  }
  const shown = document.createElement("span");
  shown.className = "value";
  label.append(name, shown);
  box.appendChild(label);
  let input;
  if (param.type === "float" || param.type === "int") {
    input = document.createElement("input");
    input.type = "range";
    input.min = param.min;
    input.max = param.max;
    input.step = param.type === "int" ? 1 : (param.max - param.min) / 500;
    input.addEventListener("input", () => {
      shown.textContent = formatNumber(input.value, param) + (param.unit ? " " + param.unit : "");
      send({ type: "set", name: param.name, value: input.value });
    });
  } else if (param.type === "bool") {
    input = document.createElement("input");
    input.type = "checkbox";
    input.addEventListener("change", () => send({ type: "set", name: param.name, value: input.checked }));
  } else if (param.type === "enum") {
    input = document.createElement("select");
    for (const choice of param.choices) input.add(new Option(choice, choice));
    input.addEventListener("change", () => send({ type: "set", name: param.name, value: input.value }));
  } else {  // color
    input = document.createElement("input");
    input.type = "color";
    input.addEventListener("input", () => send({ type: "set", name: param.name, value: input.value.slice(1) }));
  }
  input.name = param.name;
  input.id = "param-" + param.name;
  label.htmlFor = input.id;
  input.addEventListener("focus", () => { state.editing = param.name; });
  input.addEventListener("blur", () => { state.editing = null; });
  box.appendChild(input);
  const help = document.createElement("div");
  help.className = "help";
  help.textContent = [param.help, param.range].filter(Boolean).join(" ");
  box.appendChild(help);
  box.update = (value) => {
    if (param.type === "bool") input.checked = value === true;
    else if (param.type === "color") input.value = "#" + String(value).replace(/^#/, "");
    else if (param.type === "enum") input.value = value;
    else input.value = value;
    shown.textContent = param.type === "float" || param.type === "int"
      ? formatNumber(value, param) + (param.unit ? " " + param.unit : "")
      : param.type === "bool" ? "" : String(value);
  };
  return box;
}

function buildPanel(lab) {
  state.lab = lab;
  document.title = "Lab " + lab.number + ": " + lab.title + " (lab serve)";
  $("title").textContent = "Lab " + lab.number + ": " + lab.title;
  $("renderer").textContent = lab.gl_renderer + ", OpenGL " + lab.gl_version + " (" + lab.backend + ")";
  const form = $("params");
  form.replaceChildren(...lab.params.map(control));
  const picker = $("checkpoint");
  picker.length = 1;
  for (const cp of lab.checkpoints)
    picker.add(new Option(cp.name + (cp.description ? ": " + cp.description : ""), cp.name));
  const keys = $("keys");
  keys.replaceChildren();
  for (const item of [...lab.shortcuts.map((s) => [s.keys, s.action]),
                      ["drag / wheel", "the lab's mouse controls"],
                      ...lab.controls.map((c) => ["", c])]) {
    const li = document.createElement("li");
    if (item[0]) {
      const k = document.createElement("span");
      k.className = "key";
      k.textContent = item[0];
      li.append(k, " ");
    }
    li.append(item[1]);
    keys.appendChild(li);
  }
}

function showParams(values) {
  for (const box of $("params").children)
    if (box.dataset.name in values && box.dataset.name !== state.editing) box.update(values[box.dataset.name]);
}

function showProblems(problems) {
  state.problems = problems;
  const lines = [...(problems.shader_errors || [])];
  if (problems.render_error) lines.push(problems.render_error);
  if (problems.input_error) lines.push(problems.input_error);
  $("problems").hidden = lines.length === 0;
  $("problems").textContent = lines.join("\n\n");
}

// --- frames ---------------------------------------------------------------

async function showFrame(meta, blob) {
  const image = await createImageBitmap(blob);
  // Decoding finishes in any order: a frame older than the one shown is dropped.
  if (state.meta && state.meta.seq >= meta.seq) {
    image.close();
    return;
  }
  if (canvas.width !== image.width || canvas.height !== image.height) {
    canvas.width = image.width;
    canvas.height = image.height;
  }
  context2d.drawImage(image, 0, 0);
  image.close();
  state.frames += 1;
  state.meta = meta;
  $("timing").textContent = `frame ${meta.seq}, ${meta.width}x${meta.height}, drawn in ` +
    `${meta.render_ms.toFixed(1)} ms, ${meta.format.toUpperCase()}`;
}

function onMessage(event) {
  if (typeof event.data !== "string") {
    const meta = state.pendingMeta;
    state.pendingMeta = null;
    if (meta) showFrame(meta, event.data).catch((e) => setStatus("cannot show a frame: " + e, true));
    return;
  }
  const message = JSON.parse(event.data);
  if (message.type === "hello") {
    buildPanel(message.lab);
    showProblems(message.problems);
    setStatus("connected");
    sendSize();
  } else if (message.type === "frame") {
    showParams(message.params);
    showProblems(message.problems);
    $("stats").textContent = JSON.stringify({
      primitives_generated: message.stats.primitives_generated,
      render_ms: message.stats.render_ms, lab_stats: message.stats.lab_stats,
    }, null, 1);
    if (message.format === "none") state.meta = message;
    else state.pendingMeta = message;
  } else if (message.type === "ack") {
    state.unanswered -= 1;
    state.acked = Math.max(state.acked, message.version);
    if (!state.lastError) setStatus("connected");
  } else if (message.type === "error") {
    state.unanswered -= 1;
    state.lastError = message.message;
    setStatus(message.message, true);
    setTimeout(() => { if (state.lastError === message.message) state.lastError = ""; }, 4000);
  }
}

function connect() {
  const socket = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + "/ws");
  socket.binaryType = "blob";
  state.socket = socket;
  socket.onmessage = onMessage;
  socket.onclose = () => {
    setStatus("not connected: is lab serve still running? trying again...", true);
    setTimeout(connect, 2000);
  };
}

// --- size, mouse and keys ---------------------------------------------------

let sizeTimer = 0;
function sendSize() {
  clearTimeout(sizeTimer);
  sizeTimer = setTimeout(() => {
    const view = $("view");
    const max = state.lab ? state.lab.max_side : 2048;
    const width = Math.max(16, Math.min(max, Math.floor(view.clientWidth)));
    const height = Math.max(16, Math.min(max, Math.floor(view.clientHeight)));
    send({ type: "size", width, height });
  }, 100);
}
new ResizeObserver(sendSize).observe($("view"));

let dragFrom = null;
canvas.addEventListener("pointerdown", (e) => {
  dragFrom = { x: e.clientX, y: e.clientY };
  canvas.setPointerCapture(e.pointerId);
  canvas.focus();
});
canvas.addEventListener("pointermove", (e) => {
  if (!dragFrom) return;
  const scale = canvas.width / canvas.clientWidth;
  const dx = (e.clientX - dragFrom.x) * scale, dy = -(e.clientY - dragFrom.y) * scale;
  dragFrom = { x: e.clientX, y: e.clientY };
  if (dx || dy) send({ type: "drag", dx, dy });
});
const endDrag = () => { dragFrom = null; };
canvas.addEventListener("pointerup", endDrag);
canvas.addEventListener("pointercancel", endDrag);
canvas.addEventListener("wheel", (e) => {
  e.preventDefault();
  send({ type: "scroll", steps: -Math.sign(e.deltaY) });
}, { passive: false });

document.addEventListener("keydown", (e) => {
  if (e.ctrlKey || e.metaKey || e.altKey) return;
  const target = e.target.tagName;
  if (target === "INPUT" || target === "SELECT" || target === "TEXTAREA") return;
  if (!/^[a-zA-Z0-9]$/.test(e.key)) return;
  const key = e.key.toUpperCase();
  if (key !== "R" && !(state.lab && state.lab.params.some((p) => p.key === key))) return;
  e.preventDefault();
  send({ type: "key", key, shift: e.shiftKey });
});

$("checkpoint").addEventListener("change", (e) => {
  if (e.target.value) send({ type: "checkpoint", name: e.target.value });
});
$("reload").addEventListener("click", () => send({ type: "reload" }));
$("play").addEventListener("click", () => {
  state.playing = !state.playing;
  $("play").textContent = state.playing ? "Pause" : "Play";
  send({ type: "play", on: state.playing });
});

connect();
