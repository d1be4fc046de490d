// What the browser tests of the pages (koppel view, koppel edit) read off a screenshot: the share
// of pixels darker than `light` in some channel (ink) and the number of distinct colours (to 4
// bits a channel), so that a blank or one-colour page fails.
export function inkOf(png, light) {
  let ink = 0;
  const colours = new Set();
  for (let i = 0; i < png.data.length; i += 4) {
    const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
    if (r < light || g < light || b < light) ink++;
    colours.add((r >> 4) << 8 | (g >> 4) << 4 | (b >> 4));
  }
  return { share: ink / (png.width * png.height), colours: colours.size };
}
