// Starts C-Space Lab in the page's [data-lab] element and exposes its API as window.cspacelab.
'use strict';

(function start() {
  const root = document.querySelector('[data-lab]');
  const canvas = root.querySelector('canvas');
  const status = root.querySelector('.lab-status');

  function showError(message) {
    status.hidden = false;
    status.classList.add('error');
    status.textContent = message;  // textContent: never parsed as HTML
  }

  if (!document.createElement('canvas').getContext('webgl2')) {
    showError('C-Space Lab needs WebGL2, which this browser does not offer. ' +
              'Try a current Chrome, Firefox or Safari.');
    return;
  }
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());

  createCSpaceLab({
    canvas,
    print: (text) => console.log(text),
    printErr: (text) => console.warn(text),
    onAbort: (what) => showError('C-Space Lab stopped: ' + what),
  }).then((module) => {
    window.cspacelab = new CSpaceLabApi(module);
    status.hidden = true;
    canvas.focus();
  }, (err) => showError('C-Space Lab could not start: ' + err));
})();
