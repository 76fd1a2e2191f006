// The Node tests' checks: each runs on its own; a failing one prints FAIL with its first lines and
// sets the exit status, and the others still run. summary() is the last line a test prints.
let passed = 0;

export function check(what, f) {
  try {
    f();
    ++passed;
  } catch (e) {
    console.error(`FAIL ${what}: ${e.message.split('\n').slice(0, 8).join('\n')}`);
    process.exitCode = 1;
  }
}

export function summary() {
  return `${passed} checks passed${process.exitCode ? ', some FAILED' : ''}`;
}
