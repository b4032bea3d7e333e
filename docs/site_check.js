// Run in headless Chromium by check_site.cmake, in two roles. In a copy of a built page it waits
// until MathJax has typeset the page, then lists every problem a reader would see (MathJax
// missing or failing, a formula with a TeX error, an image that did not load) and hands them to
// the page that framed it. In the driver page (which sets window.siteCheckPages) it opens each
// page's copy in turn in one frame, so one browser checks the whole site (starting Chromium once
// per page cost more than the checks), and writes every page's verdict between markers the test
// reads from the dumped DOM: "OK page", or one "page: problem" line per problem.
(function () {
  // A page whose checker has not answered in this long (virtual time) is reported as unfinished.
  var PAGE_TIMEOUT_MS = 60000;

  function report(lines) {
    var out = document.createElement('pre');
    out.textContent = 'SITECHECK-BEGIN\n' + lines.join('\n') + '\nSITECHECK-END';
    document.body.appendChild(out);
  }

  function runDriver(pages) {
    var frame = document.createElement('iframe');
    frame.style.width = '1280px';  // a desktop window: MathJax measures the text it lays out
    frame.style.height = '2400px';
    document.body.appendChild(frame);
    var lines = [], index = -1, timer = null;
    function next() {
      clearTimeout(timer);
      index += 1;
      if (index === pages.length) {
        frame.remove();  // its timers would keep the browser busy until the time budget ends
        report(lines);
        return;
      }
      timer = setTimeout(function () {
        lines.push(pages[index] + ': the checker did not finish');
        next();
      }, PAGE_TIMEOUT_MS);
      frame.src = pages[index].replace(/\.html$/, '.sitecheck.html');
    }
    window.addEventListener('message', function (event) {
      var verdict = event.data && event.data.siteCheck;
      if (!verdict || verdict.page !== pages[index]) return;  // a page given up on answering late
      if (verdict.problems.length === 0) lines.push('OK ' + verdict.page);
      verdict.problems.forEach(function (problem) {
        lines.push(verdict.page + ': ' + problem.replace(/\n/g, ' '));
      });
      next();
    });
    next();
  }

  function checkPage() {
    var problems = [];
    function done() {
      var page = decodeURIComponent(location.pathname.split('/').pop()).replace(/\.sitecheck\.html$/, '.html');
      if (window.parent !== window) window.parent.postMessage({siteCheck: {page: page, problems: problems}}, '*');
      else report(problems);
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
        done();
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
        done();
      });
    }
    if (document.readyState === 'complete') checkMath();
    else window.addEventListener('load', checkMath);
  }

  if (window.siteCheckPages) runDriver(window.siteCheckPages);
  else checkPage();
})();
