// The few texts the page cannot give exactly as the native tools do, each
// with the reason (docs/WEB.md, "Where the page differs"). Everything else
// is compared exactly; these are compared with their numbers taken out, and
// the numbers held to the rule that explains them.

// The numbers of a text, and the text with each replaced by '#'.
function numbersOf(text) {
  const numbers = [];
  const shape = text.replace(/-?\d+(?:\.\d+)?(?:e[-+]?\d+)?/gi, (n) => {
    numbers.push(n);
    return '#';
  });
  return { shape, numbers };
}

// tinygltf holds a byte offset in a size_t, 32 bits in WebAssembly: an
// offset past 4 GiB is kept modulo 2^32, or as 2^32 - 1 where it is past
// 2^64 - 1 as well; the view is refused either way, as natively.
function offsetIn32Bits(page, native) {
  const [p, n] = [BigInt(page), BigInt(native)];
  return p === n || (n >= 2n ** 32n && (p === n % 2n ** 32n || p === 2n ** 32n - 1n));
}

const differences = {
  // The camera's field of view comes from tan and atan: glibc's are
  // correctly rounded, emscripten's (musl's) within an ulp, so the last
  // digit may differ.
  'right-handed-camera.pov': (page, native) =>
    Math.abs(Number(page) - Number(native)) <= 4e-15 * Math.abs(Number(native)),
  'buffer-view-offset-2-pow-64.gltf': offsetIn32Bits,
  'buffer-view-offset-wraps.gltf': offsetIn32Bits,
};

// Whether `page` (a text the page gave for the file named `name`) is what
// `native` says, allowing for the file's known difference if it has one.
export function sameAsNative(name, page, native) {
  if (page === native) return true;
  const within = differences[name];
  if (!within) return false;
  const a = numbersOf(page);
  const b = numbersOf(native);
  return a.shape === b.shape && a.numbers.length === b.numbers.length &&
         a.numbers.every((n, i) => within(n, b.numbers[i]));
}
