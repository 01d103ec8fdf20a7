// The render settings form: sfrender's options (width, height, spp,
// adaptive, depth, fov, threads). An empty field leaves the option to
// sfrender's default or the scene's own view.

const NUMBER_FIELDS = { width: 'width', height: 'height', spp: 'spp', depth: 'depth', fov: 'fov', threads: 'threads-setting' };

// "", "off" or "false": off; "on" or "true": sfrender's default threshold;
// a number: that threshold (sfrender refuses one out of range).
function adaptiveValue(text) {
  const value = text.trim().toLowerCase();
  if (value === '' || value === 'off' || value === 'false') return false;
  if (value === 'on' || value === 'true') return true;
  return Number(value);
}

export function readSettings(form) {
  const options = {};
  for (const [option, id] of Object.entries(NUMBER_FIELDS)) {
    const input = form.querySelector(`#${id}`);
    if (input.disabled || input.value.trim() === '') continue;
    // A value that is no number goes as typed: sfrender's check words the error.
    const value = Number(input.value);
    options[option] = Number.isFinite(value) ? value : input.value;
  }
  options.adaptive = adaptiveValue(form.querySelector('#adaptive').value);
  return options;
}

export function watchSettings(form, onChange) {
  form.addEventListener('input', onChange);
  form.addEventListener('submit', (event) => event.preventDefault());
}
