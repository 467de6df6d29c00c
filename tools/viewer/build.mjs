// Bundles the viewer (src/) with three.js into the one page the tool embeds:
//   node build.mjs          writes ../../src/AcDream.Core.Physics.Tool/View/viewer.html
//   node build.mjs --check  builds in memory and fails when the committed page differs (CI runs this, so the
//                           committed page is provably built from the sources and the locked packages)
import { build } from 'esbuild';
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const target = join(here, '..', '..', 'src', 'AcDream.Core.Physics.Tool', 'View', 'viewer.html');

const result = await build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'inline',
  write: false,
  logLevel: 'warning',
  charset: 'utf8',
});
let script = result.outputFiles[0].text.trimEnd();
// The script is inlined in a script element: no "</script" may appear in it (esbuild escapes those in strings already).
if (/<\/script/i.test(script)) throw new Error('the bundle contains "</script"');
if (script.includes('/*acdream-view-data*/')) throw new Error('the bundle contains the data placeholder');
const style = readFileSync(join(here, 'src', 'style.css'), 'utf8').trim();
const page = readFileSync(join(here, 'src', 'page.html'), 'utf8')
  .replace('/*acdream-view-style*/', () => style)
  .replace('/*acdream-view-script*/', () => script);

if (process.argv.includes('--check')) {
  let committed = '';
  try { committed = readFileSync(target, 'utf8'); } catch { /* missing: differs */ }
  if (committed !== page) {
    console.error(`viewer page: ${target} differs from a fresh build of tools/viewer (run: npm ci && npm run build, then commit)`);
    process.exit(1);
  }
  console.log(`viewer page: the committed page matches a fresh build (${page.length} bytes)`);
} else {
  writeFileSync(target, page);
  console.log(`viewer page written: ${target} (${page.length} bytes)`);
}
