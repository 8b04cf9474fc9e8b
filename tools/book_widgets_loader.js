// Template for book/_static/vendor/labkit_widgets.js (tools/book_assets.py
// fills in the module list). Loaded after RequireJS and before the ipywidgets HTML
// manager on pages that hold saved widget state. Everything is served from
// this book's _static folder: nothing is fetched from a CDN.
(function () {
  var here = document.currentScript.src;
  var vendor = here.slice(0, here.lastIndexOf("/") + 1);
  var modules = __MODULES__;

  // Third-party widget modules (AMD builds copied from their Python packages).
  var paths = {};
  modules.forEach(function (name) {
    paths[name] = vendor + "widgets/" + name + "/index";
  });
  // The bundled modules (@jupyter-widgets/base, controls, html-manager and
  // html-manager/dist/libembed-amd) look for their icon fonts next to the URL
  // RequireJS gives their own name: make that URL our copy's folder.
  paths["@jupyter-widgets"] = vendor + "jupyter-widgets";
  paths["@jupyter-widgets/html-manager/dist"] = vendor + "jupyter-widgets";
  requirejs.config({ paths: paths });
  window.__jupyter_widgets_assets_path__ = vendor + "jupyter-widgets/";

  // The manager falls back to this "CDN" for a module it cannot find: keep
  // even that fallback on this server (a missing module is a local 404).
  document.currentScript.setAttribute(
    "data-jupyter-widgets-cdn", vendor + "widgets/missing/");

  // ipywidgets 8 typesets widget labels with the MathJax 2 call
  // MathJax.Hub.Queue(["Typeset", MathJax.Hub, element]); the book loads
  // MathJax 3, which has no Hub. Give each MathJax object a small Hub that
  // forwards to MathJax 3, so labelled widgets render on pages with math.
  function withHub(mathjax) {
    if (mathjax && typeof mathjax === "object" && !mathjax.Hub) {
      mathjax.Hub = {
        Queue: function (job) {
          var element = job && job[2];
          var mj = window.MathJax;
          var ready = mj && mj.startup && mj.startup.promise;
          if (!ready) return;
          ready.then(function () {
            return window.MathJax.typesetPromise(element ? [element] : undefined);
          }).catch(function (err) { console.warn("MathJax:", err); });
        },
      };
    }
    return mathjax;
  }
  var current = withHub(window.MathJax);
  Object.defineProperty(window, "MathJax", {
    configurable: true,
    get: function () { return current; },
    set: function (value) { current = withHub(value); },
  });
})();
