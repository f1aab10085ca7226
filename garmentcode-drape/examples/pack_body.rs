//! Packs a body mesh (OBJ, metres) and its part segmentation (the reference's JSON) into the
//! compact form of the built-in bodies:
//!
//! `cargo run -p garmentcode-drape --example pack_body -- BODY.obj [SEGMENTATION.json] OUT.body`
//!
//! The built-in bodies are GarmentCode's `assets/bodies/NAME.obj`, with
//! `ggg_body_segmentation.json` for `mean_*` and `smpl_vert_segmentation.json` for the SMPL
//! averages.

use garmentcode_drape::BodyMesh;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (obj, parts, out) = match args.as_slice() {
        [obj, out] => (obj, None, out),
        [obj, parts, out] => (obj, Some(parts), out),
        _ => return Err("usage: pack_body BODY.obj [SEGMENTATION.json] OUT.body".into()),
    };
    let mut body = BodyMesh::load(obj.as_ref())?;
    if let Some(parts) = parts {
        body = body.with_parts_json(&std::fs::read_to_string(parts)?, parts)?;
    }
    let packed = body.to_packed()?;
    std::fs::write(out, &packed)?;
    println!("{}: {} vertices, {} triangles, {} bytes", out, body.vertices.len(), body.faces.len(), packed.len());
    Ok(())
}
