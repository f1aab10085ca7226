//! The pattern comparator (`garmentcode_compare`): agreement with the project's
//! Python judge on a corpus of recorded verdicts, CPython float helpers bit for
//! bit, and the runtime's round trip of every reference case judged equal.

mod corpus;
mod numerics;
mod runtime;
