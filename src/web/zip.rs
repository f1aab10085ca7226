//! A zip archive writer for the "download everything" button: stored entries (no
//! compression), CRC-32, a fixed timestamp.
//!
//! The files are a few hundred kilobytes of text, so compressing them is not worth a
//! dependency; a stored archive opens everywhere. The timestamp is fixed (1980-01-01,
//! the earliest DOS date) so the same files always give the same bytes.

/// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), as zip requires.
pub fn crc32(data: &[u8]) -> u32 {
    static TABLE: std::sync::OnceLock<[u32; 256]> = std::sync::OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut t = [0u32; 256];
        for (i, slot) in t.iter_mut().enumerate() {
            let mut c = i as u32;
            for _ in 0..8 {
                c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
            }
            *slot = c;
        }
        t
    });
    let mut c = !0u32;
    for &b in data {
        c = table[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8);
    }
    !c
}

/// Why an archive cannot be written (zip's 32-bit sizes and 16-bit counts).
#[derive(Debug, PartialEq, Eq)]
pub struct ZipError(pub String);

impl std::fmt::Display for ZipError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// A stored zip archive of `files` (name, contents), in the given order.
pub fn write(files: &[(&str, &[u8])]) -> Result<Vec<u8>, ZipError> {
    const DOS_TIME: u16 = 0;
    const DOS_DATE: u16 = (1 << 5) | 1; // 1980-01-01
    const UTF8_NAMES: u16 = 1 << 11;
    if files.len() > usize::from(u16::MAX) {
        return Err(ZipError("too many files for a zip archive".into()));
    }
    let mut out = Vec::new();
    let mut central = Vec::new();
    for (name, data) in files {
        let size = u32::try_from(data.len()).map_err(|_| ZipError(format!("{name}: too large for a zip archive")))?;
        let name_len = u16::try_from(name.len()).map_err(|_| ZipError(format!("{name}: name too long")))?;
        let offset = u32::try_from(out.len()).map_err(|_| ZipError("archive too large".into()))?;
        let crc = crc32(data);
        // Local file header.
        put32(&mut out, 0x0403_4b50);
        put16(&mut out, 20); // version needed: 2.0
        put16(&mut out, UTF8_NAMES);
        put16(&mut out, 0); // stored
        put16(&mut out, DOS_TIME);
        put16(&mut out, DOS_DATE);
        put32(&mut out, crc);
        put32(&mut out, size);
        put32(&mut out, size);
        put16(&mut out, name_len);
        put16(&mut out, 0); // extra field length
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(data);
        // Central directory entry.
        put32(&mut central, 0x0201_4b50);
        put16(&mut central, 20); // made by: 2.0, MS-DOS attributes
        put16(&mut central, 20);
        put16(&mut central, UTF8_NAMES);
        put16(&mut central, 0);
        put16(&mut central, DOS_TIME);
        put16(&mut central, DOS_DATE);
        put32(&mut central, crc);
        put32(&mut central, size);
        put32(&mut central, size);
        put16(&mut central, name_len);
        put16(&mut central, 0); // extra
        put16(&mut central, 0); // comment
        put16(&mut central, 0); // disk number
        put16(&mut central, 0); // internal attributes
        put32(&mut central, 0); // external attributes
        put32(&mut central, offset);
        central.extend_from_slice(name.as_bytes());
    }
    let cd_offset = u32::try_from(out.len()).map_err(|_| ZipError("archive too large".into()))?;
    let cd_size = u32::try_from(central.len()).map_err(|_| ZipError("archive too large".into()))?;
    out.extend_from_slice(&central);
    // End of central directory.
    put32(&mut out, 0x0605_4b50);
    put16(&mut out, 0);
    put16(&mut out, 0);
    put16(&mut out, files.len() as u16);
    put16(&mut out, files.len() as u16);
    put32(&mut out, cd_size);
    put32(&mut out, cd_offset);
    put16(&mut out, 0); // comment length
    Ok(out)
}

fn put16(out: &mut Vec<u8>, v: u16) {
    out.extend_from_slice(&v.to_le_bytes());
}

fn put32(out: &mut Vec<u8>, v: u32) {
    out.extend_from_slice(&v.to_le_bytes());
}

/// Read back a stored archive written by [`write`](fn@write): `(name, contents)` per entry,
/// with every CRC checked. For tests and tools; not a general zip reader.
pub fn read_stored(zip: &[u8]) -> Result<Vec<(String, Vec<u8>)>, ZipError> {
    let bad = |m: &str| ZipError(format!("not a stored zip archive: {m}"));
    let u16_at = |i: usize| zip.get(i..i + 2).map(|b| u16::from_le_bytes([b[0], b[1]]));
    let u32_at = |i: usize| zip.get(i..i + 4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    let mut files = Vec::new();
    let mut i = 0;
    while u32_at(i) == Some(0x0403_4b50) {
        let method = u16_at(i + 8).ok_or_else(|| bad("truncated header"))?;
        if method != 0 {
            return Err(bad("compressed entry"));
        }
        let crc = u32_at(i + 14).ok_or_else(|| bad("truncated header"))?;
        let size = u32_at(i + 18).ok_or_else(|| bad("truncated header"))? as usize;
        let name_len = usize::from(u16_at(i + 26).ok_or_else(|| bad("truncated header"))?);
        let extra_len = usize::from(u16_at(i + 28).ok_or_else(|| bad("truncated header"))?);
        let name_start = i + 30;
        let data_start = name_start + name_len + extra_len;
        let name = zip.get(name_start..name_start + name_len).ok_or_else(|| bad("truncated name"))?;
        let data = zip.get(data_start..data_start + size).ok_or_else(|| bad("truncated data"))?;
        if crc32(data) != crc {
            return Err(bad("CRC mismatch"));
        }
        files.push((String::from_utf8_lossy(name).into_owned(), data.to_vec()));
        i = data_start + size;
    }
    if u32_at(i) != Some(0x0201_4b50) && !files.is_empty() {
        return Err(bad("no central directory after the entries"));
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc_of_the_check_string() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
    }

    #[test]
    fn round_trip_and_determinism() {
        let files: [(&str, &[u8]); 3] = [("a.txt", b"hello"), ("dir/b.json", b"{}"), ("empty", b"")];
        let z = write(&files).unwrap();
        assert_eq!(z, write(&files).unwrap());
        let back = read_stored(&z).unwrap();
        assert_eq!(back.len(), 3);
        assert_eq!(back[0], ("a.txt".to_string(), b"hello".to_vec()));
        assert_eq!(back[1], ("dir/b.json".to_string(), b"{}".to_vec()));
        assert_eq!(back[2], ("empty".to_string(), Vec::new()));
        // End-of-central-directory record at the very end, 22 bytes, 3 entries.
        let eocd = &z[z.len() - 22..];
        assert_eq!(&eocd[..4], &[0x50, 0x4b, 0x05, 0x06]);
        assert_eq!(u16::from_le_bytes([eocd[10], eocd[11]]), 3);
    }

    #[test]
    fn corrupt_archives_are_refused() {
        let mut z = write(&[("a", b"xyz")]).unwrap();
        z[30 + 1] ^= 0xFF; // flip a data byte
        assert!(read_stored(&z).is_err());
        assert!(read_stored(&z[..20]).is_err(), "truncated header");
    }
}
