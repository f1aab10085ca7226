//! The page's static files, compiled into the binary so that the configurator
//! works offline and from any folder: no CDN, no build step, plain HTML, CSS and JS
//! (three.js, for the drape view, vendored as its npm package ships it).

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
const DRAPE: Asset = Asset { content_type: "text/javascript; charset=utf-8", body: include_str!("assets/drape.js") };
/// three.js (MIT, <https://threejs.org>), vendored from its npm package `three` 0.170.0
/// (`build/three.module.min.js`, `examples/jsm/controls/OrbitControls.js`; licence in
/// `assets/vendor/three-LICENSE`): the drape view's renderer.
const THREE: Asset = Asset { content_type: "text/javascript; charset=utf-8", body: include_str!("assets/vendor/three.module.min.js") };
const ORBIT: Asset = Asset { content_type: "text/javascript; charset=utf-8", body: include_str!("assets/vendor/OrbitControls.js") };
const STYLE: Asset = Asset { content_type: "text/css; charset=utf-8", body: include_str!("assets/style.css") };
const ICON: Asset = Asset { content_type: "image/svg+xml", body: include_str!("assets/icon.svg") };

/// The file served at `path`, if any.
pub fn get(path: &str) -> Option<&'static Asset> {
    match path {
        "/" | "/index.html" => Some(&INDEX),
        "/app.js" => Some(&SCRIPT),
        "/view3d.js" => Some(&VIEW3D),
        "/drape.js" => Some(&DRAPE),
        "/vendor/three.module.min.js" => Some(&THREE),
        "/vendor/OrbitControls.js" => Some(&ORBIT),
        "/style.css" => Some(&STYLE),
        "/icon.svg" | "/favicon.ico" => Some(&ICON),
        _ => None,
    }
}
