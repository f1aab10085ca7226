//! The page's static files, compiled into the binary so that the configurator
//! works offline and from any folder: no CDN, no build step, plain HTML, CSS and JS.

/// A static file.
pub struct Asset {
    /// `Content-Type`.
    pub content_type: &'static str,
    /// Contents.
    pub body: &'static str,
}

const INDEX: Asset = Asset { content_type: "text/html; charset=utf-8", body: include_str!("assets/index.html") };
const SCRIPT: Asset = Asset { content_type: "text/javascript; charset=utf-8", body: include_str!("assets/app.js") };
const VIEW3D: Asset = Asset { content_type: "text/javascript; charset=utf-8", body: include_str!("assets/view3d.js") };
const STYLE: Asset = Asset { content_type: "text/css; charset=utf-8", body: include_str!("assets/style.css") };
const ICON: Asset = Asset { content_type: "image/svg+xml", body: include_str!("assets/icon.svg") };

/// The file served at `path`, if any.
pub fn get(path: &str) -> Option<&'static Asset> {
    match path {
        "/" | "/index.html" => Some(&INDEX),
        "/app.js" => Some(&SCRIPT),
        "/view3d.js" => Some(&VIEW3D),
        "/style.css" => Some(&STYLE),
        "/icon.svg" | "/favicon.ico" => Some(&ICON),
        _ => None,
    }
}
