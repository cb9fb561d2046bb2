// Bundled for the browsers: computes the golden corpus's hashes with the same shared code the
// server runs, shows them, and reports them to the test server when asked (?report=URL).
import { corpusHashes } from '../support/corpus-hashes.ts';

const hashes = corpusHashes();
(window as unknown as { baizeCorpusHashes: Record<string, string> }).baizeCorpusHashes = hashes;
document.getElementById('status')!.textContent = `${Object.keys(hashes).length} hashes computed`;
const report = new URL(window.location.href).searchParams.get('report');
if (report) void fetch(report, { method: 'POST', body: JSON.stringify({ userAgent: navigator.userAgent, hashes }) });
