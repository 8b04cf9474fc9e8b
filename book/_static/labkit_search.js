// Chinese search queries. The search index holds words that jieba cut from
// the pages ("工作空间", "话题"), but a query such as "工作空间的话题" reaches the
// browser as one run of characters. Cut each run of Chinese characters into
// the longest words the index knows (forward maximum matching); everything
// else splits as Sphinx does. Sphinx's searchtools.js uses this splitQuery
// because it is defined first.
var splitQuery = function (query) {
  var han = /[\u3400-\u9fff\uf900-\ufaff]/;
  var index = (typeof Search !== "undefined" && Search._index) || null;
  var has = Object.prototype.hasOwnProperty;
  function known(word) {
    return !!index && (has.call(index.terms, word) || has.call(index.titleterms, word));
  }
  var words = [];
  query
    .split(/[^\p{Letter}\p{Number}_\p{Emoji_Presentation}]+/gu)
    .filter(function (part) { return part; })
    .forEach(function (part) {
      part.split(/([\u3400-\u9fff\uf900-\ufaff]+)/u).forEach(function (run) {
        if (!run) return;
        if (!han.test(run) || !index) { words.push(run); return; }
        for (var i = 0; i < run.length; ) {
          var len = Math.min(run.length - i, 12);
          while (len > 1 && !known(run.substr(i, len))) len--;
          var word = run.substr(i, len);
          // A lone character the index does not know (的, 了 ...) adds nothing.
          if (len > 1 || known(word)) words.push(word);
          i += len;
        }
      });
    });
  return words;
};

// Latin terms: Sphinx's Chinese indexer keeps a short word whole when stemming
// would cut it below three letters ("qos", "dds"), but the browser stems every
// query word ("qos" -> "qo") and then finds nothing. Look a query word up in
// the form the index holds it.
(function () {
  function wrapStemmer() {
    if (typeof Stemmer === "undefined" || Stemmer.labkitWrapped) return;
    var Base = Stemmer;
    var has = Object.prototype.hasOwnProperty;
    var Wrapped = function () {
      var base = new Base();
      this.stemWord = function (word) {
        var stem = base.stemWord(word);
        var index = (typeof Search !== "undefined" && Search._index) || null;
        if (!index) return stem;
        var knows = function (w) { return has.call(index.terms, w) || has.call(index.titleterms, w); };
        // The indexer stems with Snowball, the browser with Porter: "rclpy" is
        // "rclpi" in the index but stays "rclpy" here. Take the first form the
        // index holds.
        var forms = [stem, word, stem.replace(/y$/, "i"), word.replace(/y$/, "i")];
        for (var i = 0; i < forms.length; i++) if (knows(forms[i])) return forms[i];
        return stem;
      };
    };
    Wrapped.labkitWrapped = true;
    Stemmer = Wrapped;
  }
  wrapStemmer();
  if (typeof document !== "undefined") document.addEventListener("DOMContentLoaded", wrapStemmer);
})();
