// Notes script (issue 10, scale-1500): designs shapes in WebAssembly and compares the puzzle with
// the native CLI's, byte for byte. usage: node scripts/notes/wasm_parity.mjs SHAPE.puz PARTS SEED NATIVE_OUT.puz ...
// (groups of four arguments; NATIVE_OUT from `desia design voxel ... --jobs 1 --output NATIVE_OUT.puz`).
import fs from 'node:fs';

import { loadDesiaModule } from '../../wasm/index.js';

const core = await loadDesiaModule();
const args = process.argv.slice(2);
let failed = false;
for (let k = 0; k + 3 < args.length; k += 4) {
  const [shape, parts, seed, native] = args.slice(k, k + 4);
  const start = process.hrtime.bigint();
  const result = core.designVoxel(fs.readFileSync(shape, 'utf8'), { parts: Number(parts), seed: Number(seed) });
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  const same = result.status === 'success' && result.puz === fs.readFileSync(native, 'utf8');
  failed ||= !same;
  console.log(`${shape} N=${parts} seed ${seed}: ${result.status}, ${same ? 'same bytes as native' : 'DIFFERENT'} (${seconds.toFixed(1)} s)`);
}
process.exit(failed ? 1 : 0);
