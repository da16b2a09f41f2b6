// web/tests/png.mjs: the PNG reading and image comparison the render tests share (render.mjs,
// playground.mjs): enough PNG for `rtc render`'s output, and PSNR over 8-bit RGB.
import { inflateSync } from 'node:zlib';

/** 8-bit RGB or RGBA PNG (no interlace) → { width, height, rgb }. */
export function decodePng(bytes) {
  let at = 8;
  let width = 0, height = 0, channels = 0;
  const idat = [];
  while (at < bytes.length) {
    const length = bytes.readUInt32BE(at);
    const type = bytes.toString('latin1', at + 4, at + 8);
    const data = bytes.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[12] !== 0) throw new Error('expected an 8-bit, non-interlaced PNG');
      channels = { 2: 3, 6: 4 }[data[9]];
      if (!channels) throw new Error(`PNG colour type ${data[9]} not handled`);
    } else if (type === 'IDAT') idat.push(data);
    at += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const out = Buffer.alloc(stride * height);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? out[y * stride + x - channels] : 0;
      const b = y > 0 ? out[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? out[(y - 1) * stride + x - channels] : 0;
      const p = a + b - c;
      const pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const paeth = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      const predict = [0, a, b, (a + b) >> 1, paeth][filter];
      out[y * stride + x] = (line[x] + predict) & 0xff;
    }
  }
  const rgb = Buffer.alloc(width * height * 3);
  for (let i = 0; i < width * height; i++) out.copy(rgb, i * 3, i * channels, i * channels + 3);
  return { width, height, rgb };
}

/** PSNR (dB, Infinity when equal) and the number of differing pixels between RGBA8 bytes `rgba`
 *  and RGB8 bytes `rgb` of `pixels` pixels. */
export function psnrRgbaRgb(rgba, rgb, pixels) {
  let squared = 0, differing = 0;
  for (let i = 0; i < pixels; i++) {
    let same = true;
    for (let c = 0; c < 3; c++) {
      const d = rgba[i * 4 + c] - rgb[i * 3 + c];
      squared += d * d;
      if (d !== 0) same = false;
    }
    if (!same) differing++;
  }
  const mse = squared / (pixels * 3);
  return { psnr: mse === 0 ? Infinity : 10 * Math.log10((255 * 255) / mse), differing };
}
