// Injected into a copy of each built page by check_site.cmake and run in headless Chromium:
// waits until MathJax has typeset the page, then lists every problem a reader would see
// (MathJax missing or failing, a formula with a TeX error, an image that did not load) between
// markers the test reads from the dumped DOM.
(function () {
  var problems = [];
  function report() {
    var out = document.createElement('pre');
    out.textContent = 'SITECHECK-BEGIN\n' + problems.join('\n') + '\nSITECHECK-END';
    document.body.appendChild(out);
  }
  function checkImages() {
    document.querySelectorAll('img').forEach(function (img) {
      if (!img.complete || img.naturalWidth === 0)
        problems.push('image did not load: ' + img.getAttribute('src'));
    });
    document.querySelectorAll('object').forEach(function (obj) {
      var doc = null;
      try { doc = obj.contentDocument; } catch (e) { doc = null; }
      if (doc && (!doc.querySelector('svg') || doc.querySelector('parsererror')))
        problems.push('figure did not load: ' + obj.getAttribute('data'));
    });
  }
  function findErrors(node, where) {
    if (!node) return;
    if (node.type === 'merror') {
      var text = node.data && node.data[0] && node.data[0].data ? node.data[0].data.join('') : '';
      problems.push('MathJax error in ' + where + ': ' + JSON.stringify(text));
    }
    (node.data || []).forEach(function (child) {
      if (child && typeof child === 'object') findErrors(child, where);
    });
  }
  function checkMath() {
    var formulas = document.querySelectorAll('script[type^="math/tex"]');
    var rawTex = /\\\(|\\\[/.test(document.querySelector('div.contents') ?
                                   document.querySelector('div.contents').innerText : '');
    if (typeof MathJax === 'undefined' || !MathJax.Hub) {
      if (rawTex) problems.push('MathJax did not load: formulas show as raw TeX');
      checkImages();
      report();
      return;
    }
    MathJax.Hub.Register.MessageHook('file load error', function (message) {
      problems.push('MathJax could not load ' + message[1]);
    });
    MathJax.Hub.Queue(function () {
      var jax = MathJax.Hub.getAllJax();
      jax.forEach(function (j) { findErrors(j.root, j.originalText); });
      var shown = document.querySelectorAll('.MathJax_SVG, .MathJax_SVG_Display, .MathJax');
      if (formulas.length > 0 && shown.length === 0 && jax.length === 0)
        problems.push('no formula was typeset (' + formulas.length + ' in the page)');
      document.querySelectorAll('.MathJax_Error, .merror').forEach(function (e) {
        problems.push('MathJax error: ' + e.textContent);
      });
      checkImages();
      report();
    });
  }
  if (document.readyState === 'complete') checkMath();
  else window.addEventListener('load', checkMath);
})();
