// Loads .mtlx files with the MaterialX library itself (MaterialX 1.39 compiled to WebAssembly,
// the npm package @needle-tools/materialx) and its standard data libraries, runs
// Document::validate() on each and generates a GLSL ES shader for every renderable element, so
// a document that only looks right to Glint's own reader fails here.
// usage: node materialx_validate.mjs PACKAGE_BIN_DIR FILE.mtlx... [!INVALID.mtlx...]
// Exit 1 when a FILE is invalid or an !INVALID one (a check that the check can fail) is valid.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const [bin, ...files] = process.argv.slice(2);
// The Emscripten module is an ES module that expects CommonJS's require and __dirname in Node.
globalThis.require = createRequire(import.meta.url);
globalThis.__dirname = bin;
globalThis.__filename = path.join(bin, 'JsMaterialXGenShader.js');
const { default: MaterialX } = await import(path.join(bin, 'JsMaterialXGenShader.js'));
const mx = await MaterialX({ locateFile: (name) => path.join(bin, name.endsWith('.data') ? name + '.txt' : name) });
const generator = mx.EsslShaderGenerator.create();
const context = new mx.GenContext(generator);
const libraries = mx.loadStandardLibraries(context);
console.log(`MaterialX ${mx.getVersionString()}: ${libraries.getNodeDefs().length} node definitions loaded`);

let failures = 0;
for (const argument of files) {
    const expectInvalid = argument.startsWith('!');
    const file = expectInvalid ? argument.slice(1) : argument;
    if (expectInvalid) {
        const document = mx.createDocument();
        await mx.readFromXmlString(document, fs.readFileSync(file, 'utf8'));
        document.setDataLibrary(libraries);
        const report = {};
        const valid = document.validate(report);
        console.log(`${file}: ${valid ? 'valid, but should not be' : 'invalid, as it should be: ' + report.message.trim()}`);
        failures += valid ? 1 : 0;
        continue;
    }
    const document = mx.createDocument();
    try {
        await mx.readFromXmlString(document, fs.readFileSync(file, 'utf8'));
    } catch (error) {
        console.log(`${file}: MaterialX cannot read it: ${error.message}`);
        ++failures;
        continue;
    }
    document.setDataLibrary(libraries);
    const report = {};
    if (!document.validate(report)) {
        console.log(`${file}: invalid:\n${report.message}`);
        ++failures;
        continue;
    }
    const renderable = document.getMaterialNodes();
    const shaders = [];
    for (let i = 0; i < renderable.length; ++i) {
        const element = renderable[i];
        try {
            const shader = generator.generate(element.getNamePath(), element, context);
            shaders.push(`${element.getName()} (${shader.getSourceCode('pixel').length} characters of GLSL)`);
        } catch (error) {
            console.log(`${file}: ${element.getName()}: no shader: ${mx.getExceptionMessage ? mx.getExceptionMessage(error) : error}`);
            ++failures;
        }
    }
    if (renderable.length === 0) {
        console.log(`${file}: no renderable material`);
        ++failures;
    }
    console.log(`${file}: valid; ${shaders.join(', ')}`);
}
process.exit(failures ? 1 : 0);
