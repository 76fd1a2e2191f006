// Each WebAssembly build compiles each source file once, with one set of flags (web/CMakeLists.txt):
// the explorer's build (build/web/) and the trace page's (build/web-player/, every library at
// -Oz). A target that lists another's sources again, to compile them with other flags, shows here
// as a file with two compile commands in one build.
//   node node_compile_once.mjs BUILD_DIR...
import fs from 'node:fs';
import path from 'node:path';

let failed = false;
for (const dir of process.argv.slice(2)) {
  const commands = JSON.parse(fs.readFileSync(path.join(dir, 'compile_commands.json'), 'utf8'));
  const times = new Map();
  for (const c of commands) times.set(c.file, (times.get(c.file) || 0) + 1);
  const twice = [...times].filter(([, n]) => n > 1).map(([file, n]) => `${file} (${n} times)`);
  if (twice.length) {
    failed = true;
    console.log(`FAIL ${dir}: compiled more than once: ${twice.join(', ')}`);
  } else {
    console.log(`ok ${dir}: ${commands.length} units, each file once`);
  }
}
process.exit(failed ? 1 : 0);
