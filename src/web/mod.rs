//! The web configurator (`garmentcode serve`): a page whose controls are generated
//! from the design space, and the JSON API it runs on.
//!
//! - [`http`]: the small HTTP/1.1 subset the server speaks, with its limits;
//! - [`server`]: the listener, a thread per connection;
//! - [`api`]: the endpoints, as functions from request to response (no sockets);
//! - [`drape`]: the drape view's jobs (one drape at a time, polled);
//! - [`assets`]: the page's HTML, CSS and JS, embedded in the binary;
//! - [`zip`]: the archive behind "download all".

pub mod api;
pub mod assets;
pub mod drape;
pub mod http;
pub mod server;
pub mod zip;
