/** The editor's small icons (24x24 paths, drawn in the current text colour) and its lock badge for blocks. */
const PATHS = {
  undo: 'M9 7H5V3M5.5 7.5A8 8 0 1 1 4 13',
  redo: 'M15 7h4V3M18.5 7.5A8 8 0 1 0 20 13',
  expand: 'M14 4h6v6M10 20H4v-6M20 4l-7 7M4 20l7-7',
  shrink: 'M20 10h-6V4M4 14h6v6M14 10l7-7M10 14l-7 7',
  plus: 'M12 5v14M5 12h14',
  file: 'M14 3H7a2 2 0 0 0-2 2v14a2 2 0 0 0 2 2h10a2 2 0 0 0 2-2V8zM14 3v5h5M12 18v-6M9 15l3 3 3-3',
  step: 'M5 12h9M10 7l5 5-5 5M19 5v14',
  open: 'M9 6l6 6-6 6',
  lock: 'M7 11V8a5 5 0 0 1 10 0v3M6 11h12v9H6z',
  code: 'M8 8l-4 4 4 4M16 8l4 4-4 4M13.5 6l-3 12',
  blocks: 'M4 5h9v5H4zM8 14h12v5H8zM13 7.5h4v4',
} as const;

export type IconName = keyof typeof PATHS;

const SVG = 'http://www.w3.org/2000/svg';

export function icon(name: IconName): SVGSVGElement {
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('viewBox', '0 0 24 24');
  svg.setAttribute('aria-hidden', 'true');
  svg.classList.add('lbe-icon');
  const path = document.createElementNS(SVG, 'path');
  path.setAttribute('d', PATHS[name]);
  svg.appendChild(path);
  return svg;
}

/** The lock badge shown on locked blocks (a data URI: Blockly draws it as an image). */
export const LOCK_BADGE =
  'data:image/svg+xml;utf8,' +
  encodeURIComponent(
    '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 16"><rect width="16" height="16" rx="4" fill="#1c2333" fill-opacity="0.55"/>' +
      '<path d="M5.2 7.2V5.6a2.8 2.8 0 0 1 5.6 0v1.6" fill="none" stroke="white" stroke-width="1.5"/><rect x="4" y="7.2" width="8" height="5.6" rx="1" fill="white"/></svg>',
  );

/** The badge on a text-mode function's block. */
export const TEXT_BADGE =
  'data:image/svg+xml;utf8,' +
  encodeURIComponent(
    '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 22 16"><rect width="22" height="16" rx="4" fill="#1c2333" fill-opacity="0.55"/>' +
      '<text x="11" y="11.6" font-family="monospace" font-size="9.5" font-weight="700" fill="white" text-anchor="middle">JS</text></svg>',
  );
