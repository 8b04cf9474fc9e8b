// The live 3D view in JupyterLab: meshcat's three.js viewer inside a widget. The scene
// and its changes come from the kernel through the widget's own comm (binary buffers of
// length-prefixed msgpack commands), so it works wherever JupyterLab's server runs and
// nothing polls: when the kernel is gone, the last picture simply stays.

let viewerScript = null;

async function gunzip(b64) {
  const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

function loadViewer(model) {
  // meshcat's bundle is UMD: with no module system in sight it defines window.MeshCat
  if (viewerScript === null) {
    viewerScript = gunzip(model.get("viewer_js")).then((bytes) => {
      const amd = window.define;
      window.define = undefined;
      try {
        (0, eval)(new TextDecoder().decode(bytes));
      } finally {
        window.define = amd;
      }
      return window.MeshCat;
    });
  }
  return viewerScript;
}

function play(viewer, buffer) {
  const bytes = new Uint8Array(buffer.buffer || buffer, buffer.byteOffset || 0,
                               buffer.byteLength);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let i = 0;
  while (i + 4 <= bytes.length) {
    const n = view.getUint32(i, true);
    viewer.handle_command_bytearray(bytes.subarray(i + 4, i + 4 + n));
    i += 4 + n;
  }
}

async function render({ model, el }) {
  el.style.width = "100%";
  el.style.height = model.get("height") + "px";
  el.style.position = "relative";
  el.style.overflow = "hidden";
  const MeshCat = await loadViewer(model);
  const viewer = new MeshCat.Viewer(el);
  const onMessage = (msg, buffers) => {
    if (msg && msg.type === "commands") {
      for (const buffer of buffers || []) {
        play(viewer, buffer);
      }
    }
  };
  model.on("msg:custom", onMessage);
  model.send({ type: "ready" });        // the kernel answers with the whole scene
  return () => model.off("msg:custom", onMessage);
}

export default { render };
